#include "ek/knots/table.hpp"

#include <charconv>
#include <fstream>
#include <mutex>
#include <sstream>

#include "ek/core/errors.hpp"
#include "ek/core/paths.hpp"

namespace ek {
namespace {

std::vector<std::string> split_csv_line(const std::string& line) {
  // The KnotInfo export has no quoted fields (lists use ';' inside brackets);
  // quotes are still honoured for robustness.
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cur += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cur += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

std::optional<int> parse_int_field(const std::string& value, bool required, const std::string& where) {
  if (value == "?" || value.empty()) {
    if (required) throw InputError(where + ": value is unknown ('" + value + "') but required");
    return std::nullopt;
  }
  int v = 0;
  auto [p, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
  if (ec != std::errc() || p != value.data() + value.size() || v < 0)
    throw InputError(where + ": '" + value + "' is not a non-negative integer");
  return v;
}

}  // namespace

KnotTable KnotTable::load(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file)
    throw InputError("knot table '" + path +
                     "': cannot open file (set KNOT_TABLE or the Make/CMake variable KNOT_TABLE to the "
                     "KnotInfo CSV)");
  std::stringstream text;
  text << file.rdbuf();
  if (file.bad()) throw InputError("knot table '" + path + "': read error");
  return parse(text.str(), path);
}

KnotTable KnotTable::parse(const std::string& text, const std::string& path) {
  std::istringstream in(text);
  KnotTable table;
  table.path_ = path;
  std::string line;
  if (!std::getline(in, line)) throw InputError("knot table '" + path + "': file is empty");
  const auto header = split_csv_line(line);
  std::map<std::string, size_t> col;
  for (size_t i = 0; i < header.size(); ++i) col[header[i]] = i;
  const char* required[] = {"Name",           "DT Notation", "PD Notation", "Braid Notation",
                            "Crossing Number", "Bridge Index", "Braid Index", "Symmetry Type"};
  for (const char* r : required)
    if (!col.count(r))
      throw InputError("knot table '" + path + "', row 0 (header): column '" + r + "' is missing");
  int row = 0;
  while (std::getline(in, line)) {
    ++row;
    if (line.empty() || line == "\r") continue;
    const auto fields = split_csv_line(line);
    const std::string row_at = "knot table '" + path + "', row " + std::to_string(row);
    if (fields.size() != header.size())
      throw InputError(row_at + ": " + std::to_string(fields.size()) + " fields, expected " +
                       std::to_string(header.size()));
    KnotRecord rec;
    rec.row = row;
    for (size_t i = 0; i < header.size(); ++i) rec.fields[header[i]] = fields[i];
    auto get = [&](const char* name) -> const std::string& { return fields[col.at(name)]; };
    auto at = [&](const char* name) { return row_at + ", column '" + name + "'"; };
    rec.name = get("Name");
    if (rec.name.empty() || rec.name == "?") throw InputError(at("Name") + ": empty name");
    rec.crossing_number = *parse_int_field(get("Crossing Number"), true, at("Crossing Number"));
    rec.bridge_index = parse_int_field(get("Bridge Index"), false, at("Bridge Index"));
    rec.braid_index = parse_int_field(get("Braid Index"), false, at("Braid Index"));
    if (col.count("Unknotting Number")) {
      // KnotInfo gives ranges such as "[1;2]" for unknown unknotting numbers.
      const std::string& u = get("Unknotting Number");
      if (!u.empty() && u != "?" && u.find_first_not_of("0123456789") == std::string::npos)
        rec.unknotting_number = parse_int_field(u, false, at("Unknotting Number"));
    }
    if (col.count("Alternating")) {
      const std::string& a = get("Alternating");
      if (a == "Y") rec.alternating = true;
      if (a == "N") rec.alternating = false;
    }
    rec.symmetry_type = get("Symmetry Type") == "?" ? "" : get("Symmetry Type");
    try {
      const std::string& dt = get("DT Notation");
      if (dt != "?" && !dt.empty()) rec.dt = parse_dt(dt);
    } catch (const InputError& e) {
      throw InputError(at("DT Notation") + ": " + e.what());
    }
    try {
      const std::string& pd = get("PD Notation");
      if (pd != "?" && !pd.empty()) rec.pd = parse_pd(pd);
    } catch (const InputError& e) {
      throw InputError(at("PD Notation") + ": " + e.what());
    }
    try {
      const std::string& br = get("Braid Notation");
      if (br != "?" && !br.empty()) {
        rec.braids = parse_braid_list(br);
        rec.braid = rec.braids.front();
        for (const auto& w : rec.braids)
          if (w.strands < rec.braid->strands) rec.braid = w;
      }
    } catch (const InputError& e) {
      throw InputError(at("Braid Notation") + ": " + e.what());
    }
    if (rec.crossing_number > 0) {
      if (!rec.pd) throw InputError(at("PD Notation") + ": missing for a knot with crossings");
      if (rec.pd->size() != rec.crossing_number)
        throw InputError(at("PD Notation") + ": " + std::to_string(rec.pd->size()) +
                         " crossings, but Crossing Number is " + std::to_string(rec.crossing_number));
      if (rec.dt && rec.dt->crossings() != rec.crossing_number)
        throw InputError(at("DT Notation") + ": " + std::to_string(rec.dt->crossings()) +
                         " crossings, but Crossing Number is " + std::to_string(rec.crossing_number));
    }
    if (table.by_name_.count(rec.name)) throw InputError(at("Name") + ": knot '" + rec.name + "' appears twice");
    table.by_name_[rec.name] = table.records_.size();
    table.records_.push_back(std::move(rec));
  }
  if (table.records_.empty()) throw InputError("knot table '" + path + "': no rows");
  return table;
}

const KnotTable& KnotTable::global() {
  static std::once_flag once;
  static std::unique_ptr<KnotTable> table;
  std::call_once(once, [] { table = std::make_unique<KnotTable>(load(knot_table_path())); });
  return *table;
}

const KnotRecord* KnotTable::find(const std::string& name) const {
  auto it = by_name_.find(name);
  if (it == by_name_.end() && (name == "unknot" || name == "0")) it = by_name_.find("0_1");
  return it == by_name_.end() ? nullptr : &records_[it->second];
}

const KnotRecord& KnotTable::at(const std::string& name) const {
  const KnotRecord* r = find(name);
  if (!r)
    throw InputError("unknown knot '" + name + "' (not in the knot table '" + path_ +
                     "'; names look like 3_1, 10_123, 12a_1019, 12n_838)");
  return *r;
}

std::vector<const KnotRecord*> KnotTable::with_crossings(int crossing_number) const {
  std::vector<const KnotRecord*> out;
  for (const auto& r : records_)
    if (r.crossing_number == crossing_number) out.push_back(&r);
  return out;
}

std::vector<const KnotRecord*> KnotTable::up_to_crossings(int c, bool include_unknot) const {
  std::vector<const KnotRecord*> out;
  for (const auto& r : records_)
    if (r.crossing_number <= c && (include_unknot || r.crossing_number > 0)) out.push_back(&r);
  return out;
}

}  // namespace ek
