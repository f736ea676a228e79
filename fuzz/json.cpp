// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: Json::parse (io/json.hpp) and json_field_line (io/json_position.hpp) on any bytes.
//
// - parse() is the strict reader it says it is: what it accepts has no \u escape without 4 hex
//   digits and no number outside JSON's grammar (leading zeros, "+1", ".5", "1.").
// - Only topograsp::invalid_argument may escape parse() (its documented error); anything else
//   (std::invalid_argument from a std::sto*, std::out_of_range, std::length_error, ...) is a
//   failure.
// - A value that parses dumps (one-line and indented) to text that parses again, to an equal
//   value: same kinds, same strings byte for byte, same keys in the same order, numbers equal.
// - json_field_line, on any text, JSON or not, gives a line of the text (1 to its newlines + 1).

#include <algorithm>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>
#include <typeinfo>

#include <topograsp/core/error.hpp>
#include <topograsp/io/json.hpp>
#include <topograsp/io/json_position.hpp>

#include "fuzz_input.hpp"

namespace {

using topograsp::Json;
using topograsp::fuzz::c_literal;
using topograsp::fuzz::fuzz_fail;

// Where a and b first differ ("" if they are equal).
std::string difference(const Json& a, const Json& b, const std::string& path) {
  const auto kind = [](const Json& j) {
    return j.is_null()     ? 0
           : j.is_bool()   ? 1
           : j.is_number() ? 2
           : j.is_string() ? 3
           : j.is_array()  ? 4
                           : 5;
  };
  if (kind(a) != kind(b)) return path + ": the kinds differ";
  if (a.is_bool() && a.as_bool() != b.as_bool()) return path + ": the booleans differ";
  if (a.is_number() && !(a.as_number() == b.as_number()))
    return path + ": " + topograsp::fuzz::num(a.as_number()) + " became " +
           topograsp::fuzz::num(b.as_number());
  if (a.is_string() && a.as_string() != b.as_string())
    return path + ": " + c_literal(a.as_string()) + " became " + c_literal(b.as_string());
  if (a.is_array()) {
    if (a.as_array().size() != b.as_array().size()) return path + ": the array sizes differ";
    for (std::size_t k = 0; k < a.as_array().size(); ++k) {
      std::string d =
          difference(a.as_array()[k], b.as_array()[k], path + "[" + std::to_string(k) + "]");
      if (!d.empty()) return d;
    }
  }
  if (a.is_object()) {
    if (a.as_object().size() != b.as_object().size()) return path + ": the object sizes differ";
    for (std::size_t k = 0; k < a.as_object().size(); ++k) {
      const auto& [ka, va] = a.as_object()[k];
      const auto& [kb, vb] = b.as_object()[k];
      if (ka != kb) return path + ": key " + c_literal(ka) + " became " + c_literal(kb);
      std::string d = difference(va, vb, path + "." + ka);
      if (!d.empty()) return d;
    }
  }
  return {};
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_hex(char c) { return is_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

// What in \p t (text that parse() accepted) is not JSON (RFC 8259), for the two things a lenient
// reader gets wrong: a \u escape without 4 hex digits and a number outside JSON's grammar
// -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?. "" if neither occurs.
std::string not_json(std::string_view t) {
  for (std::size_t i = 0; i < t.size();) {
    if (t[i] == '"') {
      for (++i; i < t.size() && t[i] != '"'; ++i) {
        if (t[i] != '\\') continue;
        ++i;
        if (i < t.size() && t[i] == 'u') {
          for (std::size_t k = 1; k <= 4; ++k)
            if (i + k >= t.size() || !is_hex(t[i + k]))
              return "a \\u escape without 4 hex digits at offset " + std::to_string(i - 1);
          i += 4;
        }
      }
      ++i;
      continue;
    }
    if (t[i] == '-' || t[i] == '+' || t[i] == '.' || is_digit(t[i])) {
      const std::size_t start = i;
      std::size_t j = i;
      bool ok = true;
      if (t[j] == '-') ++j;
      if (j < t.size() && t[j] == '0') {
        ++j;
      } else if (j < t.size() && is_digit(t[j])) {
        while (j < t.size() && is_digit(t[j])) ++j;
      } else {
        ok = false;
      }
      if (ok && j < t.size() && t[j] == '.') {
        ++j;
        ok = j < t.size() && is_digit(t[j]);
        while (j < t.size() && is_digit(t[j])) ++j;
      }
      if (ok && j < t.size() && (t[j] == 'e' || t[j] == 'E')) {
        ++j;
        if (j < t.size() && (t[j] == '+' || t[j] == '-')) ++j;
        ok = j < t.size() && is_digit(t[j]);
        while (j < t.size() && is_digit(t[j])) ++j;
      }
      // The number token ends at the first character that cannot continue it.
      std::size_t end = start;
      while (end < t.size() && (is_digit(t[end]) || t[end] == '-' || t[end] == '+' ||
                                t[end] == '.' || t[end] == 'e' || t[end] == 'E'))
        ++end;
      if (!ok || j != end)
        return "the number " + c_literal(t.substr(start, end - start)) + " at offset " +
               std::to_string(start);
      i = end;
      continue;
    }
    ++i;
  }
  return {};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return topograsp::fuzz::run_input(data, size, [&] {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const long lines = 1 + std::count(text.begin(), text.end(), '\n');
    for (const std::string_view path : {"", "a", "a[0]", "a.b[1].c", "[2]"}) {
      const int line = topograsp::json_field_line(text, path);
      if (line < 1 || line > lines)
        fuzz_fail("json",
                  "json_field_line gave line " + std::to_string(line) + " of a text of " +
                      std::to_string(lines),
                  "text = " + c_literal(text) + "\npath = " + c_literal(path));
    }
    Json value;
    try {
      value = Json::parse(text);
    } catch (const topograsp::invalid_argument&) {
      return;  // the documented error
    } catch (const std::exception& e) {
      fuzz_fail("json",
                std::string("parse threw ") + typeid(e).name() +
                    " (not topograsp::invalid_argument): " + e.what(),
                "text = " + c_literal(text));
    }
    if (const std::string bad = not_json(text); !bad.empty())
      fuzz_fail("json", "parse accepted text that is not JSON: " + bad,
                "text = " + c_literal(text));
    for (const int indent : {0, 2}) {
      const std::string dumped = value.dump(indent);
      Json again;
      try {
        again = Json::parse(dumped);
      } catch (const std::exception& e) {
        fuzz_fail("json",
                  "the dump (indent " + std::to_string(indent) + ") does not parse: " + e.what(),
                  "text = " + c_literal(text) + "\ndump = " + c_literal(dumped));
      }
      const std::string d = difference(value, again, "$");
      if (!d.empty())
        fuzz_fail(
            "json", "dump (indent " + std::to_string(indent) + ") and parse changed the value",
            "text = " + c_literal(text) + "\ndump = " + c_literal(dumped) + "\nat " + c_literal(d));
    }
  });
}
