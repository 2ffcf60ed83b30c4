#pragma once
// The JSON conversion of the experiments' summary structs (summary.json):
// EK_JSON_FIELDS(Type, field, ...) defines to_json and from_json with the
// field names as keys, so the experiment that writes a summary and the paper
// check, open claim or tool that reads it share one definition and the keys
// cannot drift. Works with nlohmann::json and nlohmann::ordered_json (the
// experiments write ordered_json: keys in declaration order).
//
// Types: numbers, strings, booleans, vectors, nested structs; std::optional<T>
// (a value that may be absent, e.g. a table knot's name) is null when empty.
// Reading: a missing key is an error naming the key, except for
// std::optional fields (empty).
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>

namespace nlohmann {
template <class T>
struct adl_serializer<std::optional<T>> {
  template <class BasicJsonType>
  static void to_json(BasicJsonType& j, const std::optional<T>& v) {
    if (v) j = *v;
    else j = nullptr;
  }
  template <class BasicJsonType>
  static void from_json(const BasicJsonType& j, std::optional<T>& v) {
    if (j.is_null()) v.reset();
    else v = j.template get<T>();
  }
};
}  // namespace nlohmann

namespace ek::results {

/// Reads key `name` of `j` into `value` (see the file comment).
template <class BasicJsonType, class T>
void read_field(const BasicJsonType& j, const char* name, T& value) {
  const auto it = j.find(name);
  if (it == j.end()) throw std::runtime_error(std::string("summary has no key '") + name + "'");
  it->get_to(value);
}
template <class BasicJsonType, class T>
void read_field(const BasicJsonType& j, const char* name, std::optional<T>& value) {
  const auto it = j.find(name);
  if (it == j.end()) value.reset();
  else it->get_to(value);
}

/// A summary read from JSON text or a parsed document, with the file named
/// in the error of a missing key or a wrong type.
template <class Summary, class BasicJsonType>
Summary parse_summary(const BasicJsonType& j, const std::string& where) {
  try {
    return j.template get<Summary>();
  } catch (const std::exception& e) {
    throw std::runtime_error(where + ": " + e.what() + " (written by another version? rerun the experiment)");
  }
}

}  // namespace ek::results

#define EK_JSON_TO_FIELD(v1) nlohmann_json_j[#v1] = nlohmann_json_t.v1;
#define EK_JSON_FROM_FIELD(v1) ::ek::results::read_field(nlohmann_json_j, #v1, nlohmann_json_t.v1);

/// to_json and from_json of Type over the listed fields, for every nlohmann
/// JSON type; use in Type's namespace.
#define EK_JSON_FIELDS(Type, ...)                                                                         \
  template <class BasicJsonType,                                                                          \
            ::nlohmann::detail::enable_if_t<::nlohmann::detail::is_basic_json<BasicJsonType>::value, int> = 0> \
  inline void to_json(BasicJsonType& nlohmann_json_j, const Type& nlohmann_json_t) {                      \
    NLOHMANN_JSON_EXPAND(NLOHMANN_JSON_PASTE(EK_JSON_TO_FIELD, __VA_ARGS__))                              \
  }                                                                                                       \
  template <class BasicJsonType,                                                                          \
            ::nlohmann::detail::enable_if_t<::nlohmann::detail::is_basic_json<BasicJsonType>::value, int> = 0> \
  inline void from_json(const BasicJsonType& nlohmann_json_j, Type& nlohmann_json_t) {                    \
    NLOHMANN_JSON_EXPAND(NLOHMANN_JSON_PASTE(EK_JSON_FROM_FIELD, __VA_ARGS__))                            \
  }
