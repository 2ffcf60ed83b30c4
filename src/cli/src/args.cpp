#include "args.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "ek/core/errors.hpp"

namespace ek::cli {

std::vector<double> parse_number_list(const std::string& text, const std::string& what) {
  std::vector<double> out;
  for (size_t pos = 0; !text.empty();) {
    const size_t end = std::min(text.find(',', pos), text.size());
    out.push_back(parse_number(text.substr(pos, end - pos), what));
    if (end == text.size()) break;
    pos = end + 1;
  }
  return out;
}

Eigen::Vector3d parse_vec3(const std::string& text, const std::string& option) {
  std::vector<double> v;
  try {
    v = parse_number_list(text, option);
  } catch (const InputError&) {
    v.clear();
  }
  if (v.size() != 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    throw InputError(option + " expects X,Y,Z, not '" + text + "'");
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

ArgParser::ArgParser(std::string command, std::string synopsis)
    : command_(std::move(command)), synopsis_(std::move(synopsis)) {}

namespace {
std::vector<std::string> split_names(const std::string& names) {
  std::vector<std::string> out;
  std::stringstream ss(names);
  std::string n;
  while (std::getline(ss, n, ',')) out.push_back(n);
  return out;
}
}  // namespace

void ArgParser::positional(const std::string& name, std::string* value, const std::string& help) {
  pos_.push_back({name, help, value});
}

void ArgParser::rest(const std::string& name, std::vector<std::string>* values, const std::string& help) {
  rest_ = values;
  rest_name_ = name;
  rest_help_ = help;
}

void ArgParser::option(const std::string& names, std::string* value, const std::string& help) {
  opts_.push_back({split_names(names), help, true, [value](const std::string&, const std::string& v) { *value = v; }});
}
void ArgParser::option(const std::string& names, double* value, const std::string& help) {
  opts_.push_back({split_names(names), help, true,
                   [value](const std::string& n, const std::string& v) { *value = parse_number(v, n); }});
}
void ArgParser::option(const std::string& names, int* value, const std::string& help) {
  opts_.push_back({split_names(names), help, true, [value](const std::string& n, const std::string& v) {
                     long long x = parse_integer(v, n);
                     if (x < INT32_MIN || x > INT32_MAX) throw InputError(n + ": '" + v + "' is out of range");
                     *value = static_cast<int>(x);
                   }});
}
void ArgParser::option(const std::string& names, long long* value, const std::string& help) {
  opts_.push_back({split_names(names), help, true,
                   [value](const std::string& n, const std::string& v) { *value = parse_integer(v, n); }});
}
void ArgParser::option(const std::string& names, std::optional<double>* value, const std::string& help) {
  opts_.push_back({split_names(names), help, true,
                   [value](const std::string& n, const std::string& v) { *value = parse_number(v, n); }});
}
void ArgParser::option(const std::string& names, std::optional<int>* value, const std::string& help) {
  opts_.push_back({split_names(names), help, true, [value](const std::string& n, const std::string& v) {
                     long long x = parse_integer(v, n);
                     if (x < INT32_MIN || x > INT32_MAX) throw InputError(n + ": '" + v + "' is out of range");
                     *value = static_cast<int>(x);
                   }});
}
void ArgParser::option(const std::string& names, std::optional<std::string>* value, const std::string& help) {
  opts_.push_back({split_names(names), help, true, [value](const std::string&, const std::string& v) { *value = v; }});
}
void ArgParser::option(const std::string& names, std::vector<std::string>* values, const std::string& help) {
  opts_.push_back(
      {split_names(names), help, true, [values](const std::string&, const std::string& v) { values->push_back(v); }});
}
void ArgParser::flag(const std::string& names, bool* value, const std::string& help) {
  opts_.push_back({split_names(names), help, false, [value](const std::string&, const std::string&) { *value = true; }});
}

ArgParser::Opt* ArgParser::find(const std::string& name) {
  for (auto& o : opts_)
    for (auto& n : o.names)
      if (n == name) return &o;
  return nullptr;
}

bool ArgParser::given(const std::string& name) const {
  for (const auto& o : opts_)
    for (const auto& n : o.names)
      if (n == name) return o.seen;
  return false;
}

bool ArgParser::parse(int argc, char** argv, int first) {
  size_t npos = 0;
  for (int i = first; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      std::cout << usage();
      return false;
    }
    if (a.size() > 1 && a[0] == '-' && !(std::isdigit(static_cast<unsigned char>(a[1])) || a[1] == '.')) {
      std::string value;
      bool inline_value = false;
      auto eq = a.find('=');
      if (a.rfind("--", 0) == 0 && eq != std::string::npos) {
        value = a.substr(eq + 1);
        a = a.substr(0, eq);
        inline_value = true;
      }
      Opt* o = find(a);
      if (!o) throw InputError("knots " + command_ + ": unknown option '" + a + "' (see knots " + command_ + " --help)");
      if (o->takes_value) {
        if (!inline_value) {
          if (i + 1 >= argc) throw InputError("knots " + command_ + ": option " + a + " needs a value");
          value = argv[++i];
        }
        o->set(a, value);
      } else {
        if (inline_value) throw InputError("knots " + command_ + ": option " + a + " takes no value");
        o->set(a, "");
      }
      o->seen = true;
    } else if (npos < pos_.size()) {
      *pos_[npos++].value = a;
    } else if (rest_) {
      rest_->push_back(a);
    } else {
      throw InputError("knots " + command_ + ": unexpected argument '" + a + "'");
    }
  }
  if (npos < pos_.size())
    throw InputError("knots " + command_ + ": missing argument " + pos_[npos].name + " (usage: knots " + command_ + " " +
                     synopsis_ + ")");
  return true;
}

std::string ArgParser::usage() const {
  std::ostringstream out;
  out << "usage: knots " << command_ << " " << synopsis_ << "\n";
  for (const auto& p : pos_) out << "  " << p.name << "\n      " << p.help << "\n";
  if (rest_) out << "  " << rest_name_ << "\n      " << rest_help_ << "\n";
  for (const auto& o : opts_) {
    out << "  ";
    for (size_t k = 0; k < o.names.size(); ++k) out << (k ? ", " : "") << o.names[k];
    if (o.takes_value) out << " VALUE";
    out << "\n      " << o.help << "\n";
  }
  return out.str();
}

}  // namespace ek::cli
