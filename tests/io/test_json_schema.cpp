// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <topograsp/io/json_schema.hpp>

using namespace topograsp;

namespace {

// A schema with every keyword validate_json checks.
const Json& pose_schema() {
  static const Json s = Json::parse(R"({
    "$schema": "https://json-schema.org/draft/2020-12/schema",
    "title": "a grasp", "description": "for the test", "$comment": "annotations are ignored",
    "type": "object",
    "required": ["name", "pose", "joints"],
    "additionalProperties": false,
    "properties": {
      "name": {"type": "string"},
      "kind": {"enum": ["human", "robot"]},
      "version": {"const": 2},
      "count": {"type": "integer", "minimum": 0, "maximum": 10},
      "pose": {"$ref": "#/$defs/pose"},
      "maybe": {"anyOf": [{"$ref": "#/$defs/pose"}, {"type": "null"}]},
      "joints": {"type": "object", "additionalProperties": {"type": "number"}},
      "any": true
    },
    "$defs": {
      "pose": {"type": "object", "required": ["position"], "additionalProperties": false,
               "properties": {"position": {"type": "array", "items": {"type": "number"},
                                           "minItems": 3, "maxItems": 3}}}
    }
  })");
  return s;
}

std::vector<std::string> check(const char* text) {
  return validate_json(Json::parse(text), pose_schema());
}

}  // namespace

TEST_CASE("validate_json accepts what conforms", "[io][json][schema]") {
  CHECK(check(R"({"name": "a", "pose": {"position": [0, 1, 2]}, "joints": {}})").empty());
  CHECK(check(R"({"name": "a", "kind": "robot", "version": 2, "count": 10, "maybe": null,
                  "pose": {"position": [0, 1, 2]}, "joints": {"knuckle": 0.5},
                  "any": [1, "x"]})")
            .empty());
  CHECK(check(R"({"name": "a", "maybe": {"position": [1, 2, 3]}, "pose": {"position": [0, 1, 2]},
                  "joints": {}})")
            .empty());
}

TEST_CASE("validate_json says where and how a document breaks the schema",
          "[io][json][schema][bad-input]") {
  using Catch::Equals;
  CHECK_THAT(check(R"({"name": 3, "pose": {"position": [0, 1, 2]}, "joints": {}})"),
             Equals(std::vector<std::string>{"/name: expected string, got number"}));
  CHECK_THAT(check(R"({"pose": {"position": [0, 1, 2]}, "joints": {}})"),
             Equals(std::vector<std::string>{"/: lacks \"name\""}));
  CHECK_THAT(check(R"({"name": "a", "pose": {"position": [0, 1]}, "joints": {}})"),
             Equals(std::vector<std::string>{"/pose/position: expected at least 3 items, got 2"}));
  CHECK_THAT(check(R"({"name": "a", "pose": {"position": [0, 1, "2"]}, "joints": {}})"),
             Equals(std::vector<std::string>{"/pose/position/2: expected number, got string"}));
  CHECK_THAT(check(R"({"name": "a", "pose": {"position": [0, 1, 2]}, "joints": {}, "x": 1})"),
             Equals(std::vector<std::string>{"/x: no value is allowed here"}));
  CHECK_THAT(
      check(R"({"name": "a", "kind": "alien", "pose": {"position": [0, 1, 2]},
                       "joints": {}})"),
      Equals(std::vector<std::string>{"/kind: \"alien\" is not one of [\"human\",\"robot\"]"}));
  CHECK_THAT(check(R"({"name": "a", "version": 1, "pose": {"position": [0, 1, 2]},
                       "joints": {}})"),
             Equals(std::vector<std::string>{"/version: expected 2"}));
  CHECK_THAT(check(R"({"name": "a", "count": 1.5, "pose": {"position": [0, 1, 2]},
                       "joints": {}})"),
             Equals(std::vector<std::string>{"/count: expected integer, got number"}));
  CHECK_THAT(check(R"({"name": "a", "count": 11, "pose": {"position": [0, 1, 2]},
                       "joints": {}})"),
             Equals(std::vector<std::string>{"/count: 11 is above the maximum 10"}));
  CHECK_THAT(check(R"({"name": "a", "pose": {"position": [0, 1, 2]}, "joints": {"a": "x"}})"),
             Equals(std::vector<std::string>{"/joints/a: expected number, got string"}));
  const std::vector<std::string> any =
      check(R"({"name": "a", "maybe": 3, "pose": {"position": [0, 1, 2]}, "joints": {}})");
  REQUIRE(any.size() == 1);
  CHECK_THAT(any[0], Catch::StartsWith("/maybe: matches none of anyOf: (1) /maybe: expected "
                                       "object, got number; (2) /maybe: expected null"));
  // Several faults: each listed, at most max_errors of them.
  const Json bad = Json::parse(R"({"name": 1, "kind": 2, "count": -1, "pose": {}, "joints": 3})");
  CHECK(validate_json(bad, pose_schema()).size() == 5);
  CHECK(validate_json(bad, pose_schema(), 2).size() == 2);
}

TEST_CASE("validate_json refuses a schema that asks what it does not check",
          "[io][json][schema][bad-input]") {
  const Json doc = Json::parse(R"({"name": "a"})");
  CHECK_THROWS_WITH(
      validate_json(doc, Json::parse(R"({"properties": {"name": {"pattern": "^a"}}})")),
      Catch::Contains("schema") && Catch::Contains("\"pattern\"") && Catch::Contains("at /name"));
  CHECK_THROWS_WITH(validate_json(doc, Json::parse(R"({"$ref": "other.json#/x"})")),
                    Catch::Contains("only \"#/$defs/NAME\""));
  CHECK_THROWS_WITH(validate_json(doc, Json::parse(R"({"$ref": "#/$defs/none"})")),
                    Catch::Contains("names no definition"));
  CHECK_THROWS_WITH(validate_json(doc, Json::parse(R"({"properties": {"name": 3}})")),
                    Catch::Contains("must be an object or a boolean"));
  CHECK_THROWS_WITH(
      validate_json(doc,
                    Json::parse(R"({"$defs": {"a": {"$ref": "#/$defs/a"}}, "$ref": "#/$defs/a"})")),
      Catch::Contains("deeper than 64"));
}
