// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Checks a Json document against a JSON Schema (draft 2020-12) written with a stated subset of
/// its keywords: enough for the schemas the library ships (data/schemas/), strict about the rest.
/// docs/transfer.md, "results.json".
#pragma once

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/io/json.hpp>

namespace topograsp {

/// The keywords validate_json() checks: type (a name or a list; "integer" is a number without a
/// fractional part), enum, const, properties, required, additionalProperties (false or a schema),
/// items, minItems, maxItems, minimum, maximum, anyOf, $ref (to "#/$defs/NAME" of the root
/// schema) and $defs; the annotations $schema, $id, $comment, title and description are read and
/// ignored. Any other keyword is refused, so a schema never passes a document on a rule it did not
/// check.
inline constexpr std::string_view json_schema_keywords[] = {
    "type",       "enum",     "const",    "properties", "required", "additionalProperties",
    "items",      "minItems", "maxItems", "minimum",    "maximum",  "anyOf",
    "$ref",       "$defs",    "$schema",  "$id",        "$comment", "title",
    "description"};

namespace detail {

inline const char* json_type_name(const Json& v) {
  if (v.is_null()) return "null";
  if (v.is_bool()) return "boolean";
  if (v.is_number()) return "number";
  if (v.is_string()) return "string";
  if (v.is_array()) return "array";
  return "object";
}

inline bool json_has_type(const Json& v, std::string_view type) {
  if (type == "integer") return v.is_number() && std::floor(v.as_number()) == v.as_number();
  if (type == "number") return v.is_number();
  return type == json_type_name(v);
}

inline bool json_equal(const Json& a, const Json& b) { return a.dump(0) == b.dump(0); }

class SchemaCheck {
 public:
  SchemaCheck(const Json& root, std::size_t max_errors) : root_(root), max_(max_errors) {}

  std::vector<std::string> errors;

  void check(const Json& v, const Json& schema, const std::string& path, int depth = 0) {
    if (errors.size() >= max_) return;
    if (depth > 64) throw_invalid_argument("schema", "$ref nests deeper than 64 levels");
    if (schema.is_bool()) {
      if (!schema.as_bool()) fail(path, "no value is allowed here");
      return;
    }
    if (!schema.is_object())
      throw_invalid_argument("schema", "a schema must be an object or a boolean at " + path);
    for (const auto& [key, rule] : schema.as_object()) {
      bool known = false;
      for (std::string_view k : json_schema_keywords) known = known || k == key;
      if (!known)
        throw_invalid_argument("schema", "the keyword \"" + key +
                                             "\" is not one validate_json checks (at " + path +
                                             "); the schema would pass documents it did not check");
      (void)rule;
    }
    if (schema.contains("$ref")) check(v, resolve(schema.at("$ref").as_string()), path, depth + 1);
    if (schema.contains("type") && !type_matches(v, schema.at("type"))) {
      fail(path, "expected " + type_list(schema.at("type")) + ", got " + json_type_name(v));
      return;
    }
    if (schema.contains("const") && !json_equal(v, schema.at("const")))
      fail(path, "expected " + schema.at("const").dump(0));
    if (schema.contains("enum")) {
      bool found = false;
      for (const Json& e : schema.at("enum").as_array()) found = found || json_equal(v, e);
      if (!found) fail(path, v.dump(0) + " is not one of " + schema.at("enum").dump(0));
    }
    if (v.is_number()) {
      if (schema.contains("minimum") && v.as_number() < schema.at("minimum").as_number())
        fail(path, v.dump(0) + " is below the minimum " + schema.at("minimum").dump(0));
      if (schema.contains("maximum") && v.as_number() > schema.at("maximum").as_number())
        fail(path, v.dump(0) + " is above the maximum " + schema.at("maximum").dump(0));
    }
    if (v.is_array()) check_array(v, schema, path, depth);
    if (v.is_object()) check_object(v, schema, path, depth);
    if (schema.contains("anyOf")) {
      std::string why;
      int k = 0;
      for (const Json& option : schema.at("anyOf").as_array()) {
        SchemaCheck trial(root_, 1);
        trial.check(v, option, path, depth + 1);
        if (trial.errors.empty()) return;
        ++k;
        why += (k == 1 ? "(" : "; (") + std::to_string(k) + ") " + trial.errors.front();
      }
      fail(path, "matches none of anyOf: " + why);
    }
  }

 private:
  const Json& root_;
  std::size_t max_;

  void fail(const std::string& path, const std::string& what) {
    if (errors.size() < max_) errors.push_back((path.empty() ? "/" : path) + ": " + what);
  }

  const Json& resolve(const std::string& ref) const {
    constexpr std::string_view prefix = "#/$defs/";
    if (ref.rfind(prefix, 0) != 0)
      throw_invalid_argument("schema", "$ref \"" + ref + "\": only \"#/$defs/NAME\" is supported");
    const std::string name = ref.substr(prefix.size());
    if (!root_.contains("$defs") || !root_.at("$defs").contains(name))
      throw_invalid_argument("schema", "$ref \"" + ref + "\" names no definition");
    return root_.at("$defs").at(name);
  }

  static bool type_matches(const Json& v, const Json& type) {
    if (type.is_string()) return json_has_type(v, type.as_string());
    for (const Json& t : type.as_array())
      if (json_has_type(v, t.as_string())) return true;
    return false;
  }

  static std::string type_list(const Json& type) {
    if (type.is_string()) return type.as_string();
    std::string s;
    for (const Json& t : type.as_array()) s += (s.empty() ? "" : " or ") + t.as_string();
    return s;
  }

  void check_array(const Json& v, const Json& schema, const std::string& path, int depth) {
    const auto n = static_cast<double>(v.as_array().size());
    if (schema.contains("minItems") && n < schema.at("minItems").as_number())
      fail(path, "expected at least " + schema.at("minItems").dump(0) + " items, got " +
                     std::to_string(v.as_array().size()));
    if (schema.contains("maxItems") && n > schema.at("maxItems").as_number())
      fail(path, "expected at most " + schema.at("maxItems").dump(0) + " items, got " +
                     std::to_string(v.as_array().size()));
    if (schema.contains("items"))
      for (std::size_t i = 0; i < v.as_array().size(); ++i)
        check(v.as_array()[i], schema.at("items"), path + "/" + std::to_string(i), depth + 1);
  }

  void check_object(const Json& v, const Json& schema, const std::string& path, int depth) {
    if (schema.contains("required"))
      for (const Json& key : schema.at("required").as_array())
        if (!v.contains(key.as_string())) fail(path, "lacks \"" + key.as_string() + "\"");
    const Json* properties = schema.contains("properties") ? &schema.at("properties") : nullptr;
    for (const auto& [key, value] : v.as_object()) {
      if (properties != nullptr && properties->contains(key)) {
        check(value, properties->at(key), path + "/" + key, depth + 1);
      } else if (schema.contains("additionalProperties")) {
        check(value, schema.at("additionalProperties"), path + "/" + key, depth + 1);
      }
    }
  }
};

}  // namespace detail

/// The ways \p document breaks \p schema (JSON Schema draft 2020-12, the keywords of
/// json_schema_keywords), each "JSON pointer: what is wrong" ("/grasps/3/closing/contacts:
/// expected integer, got string"); empty if it conforms. At most \p max_errors are listed.
/// \throws topograsp::invalid_argument naming "schema" for a schema that uses a keyword outside
/// json_schema_keywords, a $ref that is not "#/$defs/NAME" or names nothing, or that is not an
/// object or a boolean where a schema is expected.
[[nodiscard]] inline std::vector<std::string> validate_json(const Json& document,
                                                            const Json& schema,
                                                            std::size_t max_errors = 20) {
  detail::SchemaCheck c(schema, max_errors);
  c.check(document, schema, "");
  return c.errors;
}

}  // namespace topograsp
