// Declarative JSON reading: every key is declared once, where it is read, with its default,
// unit, doc and validation. The same declarations run in "document" mode (no JSON) to generate
// docs/scenario.md, so the reference cannot drift from the parser. Unknown keys, wrong types and
// out-of-range values throw InputError naming the file, the JSON path, the value and the expectation.
#pragma once
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/scenario/config.hpp"

namespace dmi::schema {

using json = nlohmann::json;

// One documented key.
struct Row {
  std::string path, type, unit, default_value, doc, constraint, condition;
  bool required = false;
};

struct Context {
  std::string file;            // for messages
  int dim = 2;                 // vector length
  std::vector<Row>* doc = nullptr;  // document mode when set
  bool accept_unusual = false;  // presets: values outside the plausible ranges accepted (scaled or laboratory models)
};

struct Spec {
  std::string unit;            // "" = dimensionless
  std::string doc;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;       // min is exclusive
  bool max_open = false;
  bool required = false;
};

// Common specs: a number > 0, any value, a number >= 0.
inline Spec positive(const std::string& unit, const std::string& doc, bool required = false) {
  return Spec{.unit = unit, .doc = doc, .min = 0, .min_open = true, .required = required};
}
inline Spec any(const std::string& unit, const std::string& doc, bool required = false) {
  return Spec{.unit = unit, .doc = doc, .required = required};
}
inline Spec nonneg(const std::string& unit, const std::string& doc) { return Spec{.unit = unit, .doc = doc, .min = 0}; }

class Obj {
 public:
  Obj(const json* j, std::string path, Context& ctx, std::string condition = "");

  void number(const char* key, double& out, const Spec& s);
  void integer(const char* key, int& out, const Spec& s);
  void boolean(const char* key, bool& out, const Spec& s);
  void string(const char* key, std::string& out, const Spec& s);
  // length = ctx.dim, or `length` when > 0 (e.g. the three spring stiffnesses of a frame support).
  void vector(const char* key, DVec& out, const Spec& s, int length = 0);
  // An array of at least min_count vectors of length ctx.dim (e.g. polygon vertices).
  void vectors(const char* key, std::vector<DVec>& out, const Spec& s, int min_count);
  // Each element one of allowed; an empty allowed list accepts any string (checked elsewhere).
  void strings(const char* key, std::vector<std::string>& out, const std::vector<std::string>& allowed, const Spec& s);
  // An enumerated string mapped to a value.
  template <class E> void choice(const char* key, E& out, const std::vector<std::pair<std::string, E>>& map, const Spec& s);
  // The raw JSON value of a key declared with a free-form type (e.g. a material object validated
  // elsewhere); nullptr when absent or documenting.
  const json* raw(const char* key, const Spec& s, const char* type, const std::string& def) { return get(key, s, type, def, ""); }
  // A nested object; absent -> its keys keep their defaults.
  Obj object(const char* key, const std::string& doc);
  // An array of objects, each read by f.
  template <class T> void array(const char* key, std::vector<T>& out, const Spec& s, const std::function<void(Obj&, T&)>& f);
  // Variant keys: in read mode true when value == option; in document mode always true, and the
  // rows declared until the returned scope ends are tagged "when <key> = option".
  bool when(const std::string& key, const std::string& value, const std::string& option);
  void end_when() { condition_ = base_condition_; }

  // Throws on any key that was present but never declared.
  void finish();

  // The object exists in the input (always true in document mode).
  bool present() const { return j_ != nullptr || ctx_.doc != nullptr; }
  const std::string& path() const { return path_; }
  Context& context() { return ctx_; }
  bool documenting() const { return ctx_.doc != nullptr; }
  [[noreturn]] void fail(const std::string& key, const json* value, const std::string& expected) const;
  // The value the user wrote under key (nullptr when absent): for messages that quote it as written.
  const json* given(const char* key) const { return j_ && j_->is_object() && j_->contains(key) ? &j_->at(key) : nullptr; }

 private:
  const json* get(const char* key, const Spec& s, const char* type, const std::string& def, const std::string& constraint);
  std::string child(const char* key) const { return path_ + "/" + key; }

  const json* j_;
  std::string path_;
  Context& ctx_;
  std::set<std::string> seen_;
  std::string condition_, base_condition_;
};

std::string range_text(const Spec& s);
std::string short_dump(const json& v);
// The candidate closest to key within a couple of edits ("did you mean"), or "" if none is that close.
std::string closest_key(const std::string& key, const std::vector<std::string>& candidates);
// Markdown reference of rows, grouped by top-level section.
std::string markdown(const std::vector<Row>& rows);

template <class E>
void Obj::choice(const char* key, E& out, const std::vector<std::pair<std::string, E>>& map, const Spec& s) {
  std::string names, def;
  for (const auto& [n, e] : map) {
    names += (names.empty() ? "" : " | ") + n;
    if (e == out) def = n;
  }
  const json* v = get(key, s, "string", def, "one of " + names);
  if (!v) return;
  if (v->is_string())
    for (const auto& [n, e] : map)
      if (*v == n) { out = e; return; }
  fail(key, v, "one of " + names);
}

template <class T>
void Obj::array(const char* key, std::vector<T>& out, const Spec& s, const std::function<void(Obj&, T&)>& f) {
  const json* v = get(key, s, "array of objects", s.required ? "" : "[]", "");
  if (documenting()) {
    T item{};
    Obj o(nullptr, child(key) + "[]", ctx_, condition_);
    f(o, item);
    return;
  }
  if (!v) return;
  if (!v->is_array()) fail(key, v, "an array of objects");
  out.clear();
  for (std::size_t i = 0; i < v->size(); ++i) {
    const json& e = (*v)[i];
    const std::string p = child(key) + "/" + std::to_string(i);
    if (!e.is_object()) fail(std::string(key) + "/" + std::to_string(i), &e, "an object");
    T item{};
    Obj o(&e, p, ctx_);
    f(o, item);
    o.finish();
    out.push_back(std::move(item));
  }
}

// when() for several options: true in read mode when value is one of them; in document mode the rows declared until
// end_when() are tagged "when <key> = a or b".
bool when_any(Obj& o, const std::string& key, const std::string& value, const std::vector<std::string>& options);

}  // namespace dmi::schema
