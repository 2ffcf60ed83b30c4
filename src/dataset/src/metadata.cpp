#include "ek/dataset/metadata.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>
#include <type_traits>

namespace ek {
namespace {

bool is_empty(const FieldValue& v) { return std::holds_alternative<std::monostate>(v); }

template <class T>
FieldKind kind_of() {
  if constexpr (std::is_same_v<T, double>) return FieldKind::Real;
  else if constexpr (std::is_same_v<T, std::string>) return FieldKind::Text;
  else if constexpr (std::is_same_v<T, std::vector<double>>) return FieldKind::List;
  else if constexpr (std::is_same_v<T, std::uint64_t>) return FieldKind::Unsigned;
  else {
    static_assert(std::is_integral_v<T>, "metadata fields are doubles, integers, flags, strings or number lists");
    return FieldKind::Integer;
  }
}

template <class T>
FieldValue to_value(const std::optional<T>& v) {
  if (!v) return std::monostate{};
  if constexpr (std::is_integral_v<T> && !std::is_same_v<T, std::uint64_t>) return static_cast<std::int64_t>(*v);
  else return *v;
}

template <class T>
std::optional<T> from_value(const FieldValue& v) {
  if (is_empty(v)) return std::nullopt;
  if constexpr (std::is_same_v<T, bool>) return std::get<std::int64_t>(v) != 0;
  else if constexpr (std::is_same_v<T, std::uint64_t>) return std::get<std::uint64_t>(v);
  else if constexpr (std::is_integral_v<T>) return static_cast<T>(std::get<std::int64_t>(v));
  else return std::get<T>(v);
}

/// The columns "old files without it" and "journal key" of the table.
struct Absent {
  WhenAbsent rule;
  FieldValue value;
};
Absent required() { return {WhenAbsent::Required, {}}; }
Absent not_recorded() { return {WhenAbsent::NotRecorded, {}}; }
Absent absent_means(FieldValue v) { return {WhenAbsent::Default, std::move(v)}; }
struct Key {
  std::string name;
  FieldValue omitted;
};
Key key(std::string name) { return {std::move(name), {}}; }
Key key_unless(std::string name, FieldValue omitted) { return {std::move(name), std::move(omitted)}; }
Key no_key() { return {}; }

#define FIELD(member) &DatasetMetadata::member, #member

template <class T>
MetadataField field(std::optional<T> DatasetMetadata::*member, std::string name, std::string unit, FieldMatch match,
                    Absent absent, Key key) {
  MetadataField f;
  f.name = std::move(name);
  f.unit = std::move(unit);
  f.match = match;
  f.absent = absent.rule;
  f.absent_value = std::move(absent.value);
  f.key = std::move(key.name);
  f.key_omitted = std::move(key.omitted);
  f.kind = kind_of<T>();
  f.get = [member](const DatasetMetadata& m) { return to_value(m.*member); };
  f.set = [member](DatasetMetadata& m, const FieldValue& v) { m.*member = from_value<T>(v); };
  return f;
}

std::vector<MetadataField> make_table() {
  constexpr auto exact = FieldMatch::Exact, relative = FieldMatch::Relative, provenance = FieldMatch::Provenance;
  const FieldValue off = std::vector<double>{}, no_moves = std::int64_t{0}, yes = std::int64_t{1};
  const FieldValue direct = std::string("direct"), hybrid = std::string("hybrid");
  const FieldValue projected = std::string("eigen-projected"), no = std::int64_t{0};
  const FieldValue even = std::string("even");
  // FIELD(member): the member and its name, which is the HDF5 attribute, the
  // JSON key and the name in difference().
  // Old files: the attributes of the first version-1 files are required; the
  // BFACF schedule had these values in every run before it was recorded (it
  // was not an option of `knots explore` or `knots dataset`), and so had the
  // relaxation method (a file from a version that relaxed by the multilevel
  // method without recording it reads as direct: extending it with a
  // multilevel run is refused, never mixed); the iteration cap, the burn-in,
  // the Newton settings of the named methods (the earliest files used the
  // exact Hessian) and the stiffness flag could differ between runs, so a
  // file without them does not know them.
  // The contact Hessian was the eigen-projected one, and short steps were
  // not damped, in every run before they were recorded; the coarse levels
  // were found by collapsing the odd vertices alone ("even").
  // Journal key: the fields added to it later are left out at the values
  // that the keys of earlier versions imply (their runs used the hybrid
  // Hessian with rigid-motion removal), so that their journals still resume.
  return {
      //    member                      unit              compared    old files            journal key
      field(FIELD(young),               "pressure",       relative,   required(),          key("young")),
      field(FIELD(poisson),             "1",              relative,   required(),          key("poisson")),
      field(FIELD(radius),              "length",         relative,   required(),          key("radius")),
      field(FIELD(vertices),            "1",              exact,      required(),          key("n")),
      field(FIELD(edge_length),         "length",         relative,   required(),          key_unless("edge", 1.0)),
      field(FIELD(tolerance),           "energy/length",  relative,   required(),          key("tol")),
      field(FIELD(contact_stiffness),   "energy/length²", relative,   required(),          key("omega")),
      field(FIELD(dhat),                "length",         relative,   required(),          key("dhat")),
      field(FIELD(twist_model),         "",               exact,      required(),          key_unless("model", "twist-free")),
      field(FIELD(relax_method),        "",               exact,      absent_means(direct), key_unless("method", direct)),
      field(FIELD(coarse_levels),       "1",              exact,      not_recorded(),      key("levels")),
      field(FIELD(coarse_continuation), "1",              exact,      not_recorded(),      key("coarse")),
      field(FIELD(coarsening),          "",               exact,      absent_means(even),
            key_unless("coarsening", even)),
      field(FIELD(newton_hessian),      "",               exact,      not_recorded(),      key_unless("hessian", hybrid)),
      field(FIELD(remove_rigid_motions), "",              exact,      not_recorded(),      key_unless("rigid", yes)),
      field(FIELD(contact_hessian),     "",               exact,      absent_means(projected), key_unless("contact", projected)),
      field(FIELD(damp_short_steps),    "",               exact,      absent_means(no),    key_unless("damp", no)),
      field(FIELD(max_iterations),      "1",              exact,      not_recorded(),      key("iterations")),
      field(FIELD(burn_in),             "samples",        exact,      not_recorded(),      no_key()),  // in sampling
      field(FIELD(sampling),            "",               exact,      required(),          key("sampling")),
      field(FIELD(grow_fugacity),       "1",              relative,   absent_means(0.40),  key("grow")),
      field(FIELD(shrink_fugacity),     "1",              relative,   absent_means(0.10),  key("shrink")),
      field(FIELD(growth_factor),       "1",              relative,   absent_means(10.0),  key("growth")),
      field(FIELD(decorrelation_moves), "moves",          exact,      absent_means(no_moves), key("decorrelation")),
      field(FIELD(seed),                "",               exact,      required(),          key("seed")),
      field(FIELD(compute_stiffness),   "",               exact,      not_recorded(),      key("stiffness")),
      field(FIELD(contact_continuation), "1",             exact,      absent_means(off),   key_unless("continuation", off)),
      field(FIELD(project_version),     "",               provenance, required(),          no_key()),
      field(FIELD(knot_table),          "",               provenance, required(),          no_key()),
      field(FIELD(created),             "",               provenance, required(),          no_key()),
  };
}

#undef FIELD

bool same(const MetadataField& f, const FieldValue& a, const FieldValue& b) {
  if (is_empty(a) || is_empty(b)) return true;  // not recorded: matches anything
  if (f.match != FieldMatch::Relative) return a == b;
  const double x = std::get<double>(a), y = std::get<double>(b);
  return x == y || std::fabs(x - y) <= 1e-12 * std::max(std::fabs(x), std::fabs(y));
}

/// A value for people: 10 significant digits, "off" for an empty list.
std::string display(const FieldValue& v) {
  struct {
    std::string operator()(std::monostate) const { return "not recorded"; }
    std::string operator()(double x) const {
      std::ostringstream s;
      s << std::setprecision(10) << x;
      return s.str();
    }
    std::string operator()(std::int64_t x) const { return std::to_string(x); }
    std::string operator()(std::uint64_t x) const { return std::to_string(x); }
    std::string operator()(const std::string& x) const { return x.empty() ? "\"\"" : x; }
    std::string operator()(const std::vector<double>& x) const { return x.empty() ? "off" : continuation_text(x); }
  } visitor;
  return std::visit(visitor, v);
}

/// A value for the journal key: 17 significant digits (exact).
std::string exact_text(const FieldValue& v) {
  if (const double* x = std::get_if<double>(&v)) {
    std::ostringstream s;
    s.precision(17);
    s << *x;
    return s.str();
  }
  if (const auto* list = std::get_if<std::vector<double>>(&v)) return continuation_text(*list);
  return display(v);
}

nlohmann::ordered_json json_value(const FieldValue& v) {
  struct {
    nlohmann::ordered_json operator()(std::monostate) const { return nullptr; }
    nlohmann::ordered_json operator()(double x) const {
      return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(nullptr);
    }
    nlohmann::ordered_json operator()(std::int64_t x) const { return x; }
    nlohmann::ordered_json operator()(std::uint64_t x) const { return x; }
    nlohmann::ordered_json operator()(const std::string& x) const { return x; }
    nlohmann::ordered_json operator()(const std::vector<double>& x) const { return x; }
  } visitor;
  return std::visit(visitor, v);
}

}  // namespace

const std::vector<MetadataField>& metadata_fields() {
  static const std::vector<MetadataField> table = make_table();
  return table;
}

std::string DatasetMetadata::difference(const DatasetMetadata& o) const {
  for (const auto& f : metadata_fields()) {
    if (f.match == FieldMatch::Provenance) continue;
    const FieldValue a = f.get(*this), b = f.get(o);
    if (!same(f, a, b)) return f.name + " " + display(a) + " vs " + display(b);
  }
  return "";
}

void DatasetMetadata::forget_unrecorded(const DatasetMetadata& o) {
  for (const auto& f : metadata_fields())
    if (is_empty(f.get(o))) f.set(*this, std::monostate{});
}

std::string DatasetMetadata::text() const {
  std::ostringstream s;
  for (const auto& f : metadata_fields()) {
    s << std::left << std::setw(22) << f.name << display(f.get(*this));
    if (!f.unit.empty()) s << " [" << f.unit << "]";
    s << "\n";
  }
  return s.str();
}

std::string DatasetMetadata::json() const {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& f : metadata_fields()) j[f.name] = json_value(f.get(*this));
  return j.dump();
}

std::string journal_key(const DatasetMetadata& meta) {
  std::string out;
  for (const auto& f : metadata_fields()) {
    if (f.key.empty()) continue;
    const FieldValue v = f.get(meta);
    if (is_empty(v) || (!is_empty(f.key_omitted) && v == f.key_omitted)) continue;
    out += (out.empty() ? "" : " ") + f.key + "=" + exact_text(v);
  }
  return out;
}

std::string continuation_text(const std::vector<double>& factors) {
  std::ostringstream s;
  s.precision(17);
  for (size_t k = 0; k < factors.size(); ++k) s << (k ? "," : "") << factors[k];
  return s.str();
}

std::optional<std::vector<double>> parse_continuation(const std::string& text) {
  std::vector<double> out;
  std::istringstream s(text);
  std::string item;
  while (std::getline(s, item, ',')) {
    char* end = nullptr;
    const double f = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || !(f > 0.0 && f < 1.0)) return std::nullopt;
    out.push_back(f);
  }
  return out;
}

}  // namespace ek
