// Reading design.json's typed records back (design/verdict, comparison, plastic_record, ...): each value checked for
// its type, a damaged document refused with the place named, "<where>.<key> is not a number" (std::runtime_error).
#pragma once
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dmi::design::record {

using nlohmann::json;

// j[key], which must be there (null allowed).
inline const json& field(const json& j, const char* key, const std::string& where) {
  if (!j.is_object() || !j.contains(key)) throw std::runtime_error(where + ": no '" + key + "'");
  return j[key];
}
inline std::string text(const json& j, const char* key, const std::string& where) {
  const json& v = field(j, key, where);
  if (!v.is_string()) throw std::runtime_error(where + "." + key + " is not a string");
  return v.get<std::string>();
}
inline double number(const json& j, const char* key, const std::string& where) {
  const json& v = field(j, key, where);
  if (!v.is_number()) throw std::runtime_error(where + "." + key + " is not a number");
  return v.get<double>();
}
// A number, or `if_null` where the document holds null (an undefined factor, an unbounded displacement).
inline double number_or(const json& j, const char* key, double if_null, const std::string& where) {
  return field(j, key, where).is_null() ? if_null : number(j, key, where);
}
// A number, or none where the document holds null.
inline std::optional<double> number_or_none(const json& j, const char* key, const std::string& where) {
  if (field(j, key, where).is_null()) return std::nullopt;
  return number(j, key, where);
}
// A number that may be left out altogether.
inline std::optional<double> number_if_there(const json& j, const char* key, const std::string& where) {
  if (!j.is_object() || !j.contains(key)) return std::nullopt;
  return number(j, key, where);
}
inline bool flag(const json& j, const char* key, const std::string& where) {
  const json& v = field(j, key, where);
  if (!v.is_boolean()) throw std::runtime_error(where + "." + key + " is not true or false");
  return v.get<bool>();
}
inline std::optional<bool> flag_or_none(const json& j, const char* key, const std::string& where) {
  if (field(j, key, where).is_null()) return std::nullopt;
  return flag(j, key, where);
}
inline int count(const json& j, const char* key, const std::string& where) {
  const json& v = field(j, key, where);
  if (!v.is_number_integer() || v.get<int>() < 0) throw std::runtime_error(where + "." + key + " is not a count");
  return v.get<int>();
}
inline const json& list(const json& j, const char* key, const std::string& where) {
  const json& v = field(j, key, where);
  if (!v.is_array()) throw std::runtime_error(where + "." + key + " is not an array");
  return v;
}
inline std::vector<double> numbers(const json& j, const char* key, const std::string& where) {
  std::vector<double> out;
  for (const json& x : list(j, key, where)) {
    if (!x.is_number()) throw std::runtime_error(where + "." + key + " holds a value that is not a number");
    out.push_back(x.get<double>());
  }
  return out;
}

// A list read item by item, reader(item, "<where>[k]"); null reads as none.
template <class T, class Reader> std::vector<T> items(const json& j, const std::string& where, Reader&& reader) {
  std::vector<T> out;
  if (j.is_null()) return out;
  if (!j.is_array()) throw std::runtime_error(where + " is not an array");
  for (std::size_t k = 0; k < j.size(); ++k) out.push_back(reader(j[k], where + "[" + std::to_string(k) + "]"));
  return out;
}

}  // namespace dmi::design::record
