#include "engine/scenario/schema.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "engine/common/error.hpp"

namespace dmi::schema {

namespace {
std::string num_text(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}
}  // namespace

// Optimal-string-alignment distance (insertions, deletions, substitutions, adjacent transpositions).
std::size_t edit_distance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::string closest_key(const std::string& key, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t bd = std::max<std::size_t>(2, key.size() / 4) + 1;  // within 2 edits (more for long keys), else none
  for (const auto& c : candidates)
    if (const std::size_t d = edit_distance(key, c); d < bd && c != key) bd = d, best = c;
  return best;
}

std::string short_dump(const json& v) {
  std::string s = v.dump();
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

std::string range_text(const Spec& s) {
  std::string r;
  if (std::isfinite(s.min)) r += std::string(s.min_open ? "> " : ">= ") + num_text(s.min);
  if (std::isfinite(s.max)) r += (r.empty() ? "" : " and ") + std::string(s.max_open ? "< " : "<= ") + num_text(s.max);
  return r;
}

Obj::Obj(const json* j, std::string path, Context& ctx, std::string condition)
    : j_(j), path_(std::move(path)), ctx_(ctx), condition_(condition), base_condition_(condition) {
  if (j_ && !j_->is_object()) throw InputError(ctx_.file, path_.empty() ? "/" : path_, short_dump(*j_), "an object");
}

void Obj::fail(const std::string& key, const json* value, const std::string& expected) const {
  throw InputError(ctx_.file, path_ + "/" + key, value ? short_dump(*value) : "", expected);
}

const json* Obj::get(const char* key, const Spec& s, const char* type, const std::string& def, const std::string& constraint) {
  seen_.insert(key);
  if (ctx_.doc) {
    Row r;
    r.path = child(key);
    r.type = type;
    r.unit = s.unit;
    r.default_value = s.required ? "" : def;
    r.doc = s.doc;
    r.constraint = constraint;
    r.condition = condition_;
    r.required = s.required;
    ctx_.doc->push_back(r);
    return nullptr;
  }
  if (!j_ || !j_->contains(key)) {
    if (s.required) {
      // A misspelling of it in the object is the likely cause: name it rather than only the missing key.
      std::vector<std::string> present;
      if (j_)
        for (auto it = j_->begin(); it != j_->end(); ++it) present.push_back(it.key());
      const std::string near = closest_key(key, present);
      throw InputError(ctx_.file, child(key), "", std::string("the required key '") + key + "' (" + type +
                                                      (s.unit.empty() ? "" : ", " + s.unit) + "): " + s.doc +
                                                      (near.empty() ? "" : " ('" + near + "' is there instead: misspelled?)"));
    }
    return nullptr;
  }
  return &j_->at(key);
}

void Obj::number(const char* key, double& out, const Spec& s) {
  const std::string rt = range_text(s);
  const json* v = get(key, s, "number", std::isnan(out) ? "" : num_text(out), rt);
  if (!v) return;
  const std::string expect = "a number" + (rt.empty() ? "" : " " + rt) + (s.unit.empty() ? "" : " (" + s.unit + ")");
  if (!v->is_number()) fail(key, v, expect);
  const double x = v->get<double>();
  const bool lo = s.min_open ? x > s.min : x >= s.min;
  const bool hi = s.max_open ? x < s.max : x <= s.max;
  if (!std::isfinite(x) || !lo || !hi) fail(key, v, expect);
  out = x;
}

void Obj::integer(const char* key, int& out, const Spec& s) {
  const std::string rt = range_text(s);
  const json* v = get(key, s, "integer", std::to_string(out), rt);
  if (!v) return;
  const std::string expect = "an integer" + (rt.empty() ? "" : " " + rt);
  if (!v->is_number_integer()) fail(key, v, expect);
  const auto x = v->get<long long>();
  if ((s.min_open ? x <= s.min : x < s.min) || (s.max_open ? x >= s.max : x > s.max)) fail(key, v, expect);
  out = static_cast<int>(x);
}

void Obj::boolean(const char* key, bool& out, const Spec& s) {
  const json* v = get(key, s, "boolean", out ? "true" : "false", "");
  if (!v) return;
  if (!v->is_boolean()) fail(key, v, "true or false");
  out = v->get<bool>();
}

void Obj::string(const char* key, std::string& out, const Spec& s) {
  const json* v = get(key, s, "string", out.empty() ? "\"\"" : "\"" + out + "\"", s.required ? "non-empty" : "");
  if (!v) return;
  if (!v->is_string()) fail(key, v, "a string");
  out = v->get<std::string>();
  if (s.required && out.empty()) fail(key, v, "a non-empty string");
}

void Obj::vector(const char* key, DVec& out, const Spec& s, int length) {
  const std::string rt = range_text(s);
  const int n = length > 0 ? length : ctx_.dim;
  std::string def;
  if (!out.empty()) {
    def = "[";
    for (std::size_t i = 0; i < out.size(); ++i) def += (i ? ", " : "") + num_text(out[i]);
    def += "]";
  }
  const std::string len = length > 0 ? "length = " + std::to_string(length) : "length = dimension";
  const json* v = get(key, s, "vector", def, len + (rt.empty() ? "" : ", each " + rt));
  if (!v) {
    if (!documenting() && !out.empty() && static_cast<int>(out.size()) != n) out.resize(n, 0.0);
    return;
  }
  const std::string expect = "an array of " + std::to_string(n) + " numbers" + (rt.empty() ? "" : " " + rt) +
                             (s.unit.empty() ? "" : " (" + s.unit + ")");
  if (!v->is_array() || static_cast<int>(v->size()) != n) fail(key, v, expect);
  DVec r;
  for (const auto& e : *v) {
    if (!e.is_number()) fail(key, v, expect);
    const double x = e.get<double>();
    const bool lo = s.min_open ? x > s.min : x >= s.min;
    const bool hi = s.max_open ? x < s.max : x <= s.max;
    if (!std::isfinite(x) || !lo || !hi) fail(key, v, expect);
    r.push_back(x);
  }
  out = r;
}

void Obj::vectors(const char* key, std::vector<DVec>& out, const Spec& s, int min_count) {
  const int n = ctx_.dim;
  const std::string expect = "an array of at least " + std::to_string(min_count) + " points, each an array of " + std::to_string(n) +
                             " numbers" + (s.unit.empty() ? "" : " (" + s.unit + ")");
  const json* v = get(key, s, "array of vectors", "", "at least " + std::to_string(min_count) + " points of length = dimension");
  if (!v) return;
  if (!v->is_array() || static_cast<int>(v->size()) < min_count) fail(key, v, expect);
  std::vector<DVec> r;
  for (const auto& p : *v) {
    if (!p.is_array() || static_cast<int>(p.size()) != n) fail(key, v, expect);
    DVec x;
    for (const auto& e : p) {
      if (!e.is_number() || !std::isfinite(e.get<double>())) fail(key, v, expect);
      x.push_back(e.get<double>());
    }
    r.push_back(x);
  }
  out = r;
}

void Obj::strings(const char* key, std::vector<std::string>& out, const std::vector<std::string>& allowed, const Spec& s) {
  std::string names;
  for (const auto& a : allowed) names += (names.empty() ? "" : " | ") + a;
  const json* v = get(key, s, "array of strings", "[]", allowed.empty() ? "" : "each one of " + names);
  if (!v) return;
  const std::string expect = allowed.empty() ? "an array of strings" : "an array of strings, each one of " + names;
  if (!v->is_array()) fail(key, v, expect);
  out.clear();
  for (const auto& e : *v) {
    bool ok = e.is_string();
    if (ok && !allowed.empty()) {
      ok = false;
      for (const auto& a : allowed) ok = ok || e == a;
    }
    if (!ok) fail(key, &e, expect);
    out.push_back(e.get<std::string>());
  }
}

Obj Obj::object(const char* key, const std::string& doc) {
  Spec s;
  s.doc = doc;
  const json* v = get(key, s, "object", "{}", "");
  if (!documenting() && v && !v->is_object()) fail(key, v, "an object");
  return Obj(v, child(key), ctx_, condition_);
}

bool Obj::when(const std::string& key, const std::string& value, const std::string& option) {
  if (documenting()) {
    condition_ = (base_condition_.empty() ? "" : base_condition_ + ", ") + key + " = " + option;
    return true;
  }
  return value == option;
}

void Obj::finish() {
  if (!j_ || documenting()) return;
  for (auto it = j_->begin(); it != j_->end(); ++it) {
    if (seen_.count(it.key())) continue;
    std::string names;
    for (const auto& k : seen_) names += (names.empty() ? "" : ", ") + k;
    const std::string near = closest_key(it.key(), std::vector<std::string>(seen_.begin(), seen_.end()));
    throw InputError(ctx_.file, child(it.key().c_str()), short_dump(it.value()),
                     "no such key here (unknown key '" + it.key() + "'" + (near.empty() ? "" : "; did you mean '" + near + "'?") +
                         "); known keys: " + names);
  }
}

namespace {
std::string cell(const std::string& s) {
  std::string r;
  for (char c : s) r += c == '|' ? std::string("\\|") : std::string(1, c);
  return r;
}
}  // namespace

std::string markdown(const std::vector<Row>& rows) {
  // A section per top-level object or array, headed by its own row; scalar top-level keys form
  // "(top level)". Sections keep the order of their first row, wherever their rows were declared.
  auto section_of = [](const Row& r) {
    const auto slash = r.path.find('/', 1);
    const bool nested = slash != std::string::npos || r.type == "object" || r.type == "array of objects";
    std::string top = nested ? r.path.substr(1, slash == std::string::npos ? std::string::npos : slash - 1) : "(top level)";
    if (top.size() > 2 && top.compare(top.size() - 2, 2, "[]") == 0) top.resize(top.size() - 2);
    return top;
  };
  std::vector<std::string> order;
  std::map<std::string, std::vector<const Row*>> groups;
  for (const Row& r : rows) {
    const std::string top = section_of(r);
    if (!groups.count(top)) order.push_back(top);
    groups[top].push_back(&r);
  }
  std::ostringstream os;
  for (const std::string& top : order) {
    os << "\n### `" << top << "`\n\n| key | type | unit | default | allowed | description |\n|---|---|---|---|---|---|\n";
    for (const Row* r : groups[top]) {
      std::string doc = r->doc;
      if (!r->condition.empty()) doc = "*(when " + r->condition + ")* " + doc;
      os << "| `" << r->path << "` | " << r->type << " | " << (r->unit.empty() ? "–" : r->unit) << " | "
         << (r->required ? "**required**" : (r->default_value.empty() ? "–" : "`" + r->default_value + "`")) << " | "
         << (r->constraint.empty() ? "–" : cell(r->constraint)) << " | " << cell(doc) << " |\n";
    }
  }
  return os.str();
}

bool when_any(Obj& o, const std::string& key, const std::string& value, const std::vector<std::string>& options) {
  std::string label;
  for (const auto& option : options) label += (label.empty() ? "" : " or ") + option;
  o.when(key, value, label);
  return o.documenting() || std::find(options.begin(), options.end(), value) != options.end();
}

}  // namespace dmi::schema
