// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Json: a small JSON value with a writer and a strict reader, enough for results files and the
/// tests that check their schema. Objects keep their keys in insertion order.
#pragma once

#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include <topograsp/core/error.hpp>

namespace topograsp {

/// A JSON value: null, boolean, number, string, array or object.
class Json {
 public:
  using Array = std::vector<Json>;
  using Object = std::vector<std::pair<std::string, Json>>;

  Json() = default;  ///< null
  Json(std::nullptr_t) {}
  Json(bool b) : v_(b) {}
  Json(double d) : v_(d) {}
  Json(int i) : v_(static_cast<double>(i)) {}
  Json(long i) : v_(static_cast<double>(i)) {}
  Json(long long i) : v_(static_cast<double>(i)) {}
  Json(unsigned long i) : v_(static_cast<double>(i)) {}
  Json(const char* s) : v_(std::string(s)) {}
  Json(std::string s) : v_(std::move(s)) {}
  Json(std::string_view s) : v_(std::string(s)) {}
  Json(Array a) : v_(std::move(a)) {}
  Json(Object o) : v_(std::move(o)) {}

  /// An empty array / object.
  [[nodiscard]] static Json array() { return Json(Array{}); }
  [[nodiscard]] static Json object() { return Json(Object{}); }

  [[nodiscard]] bool is_null() const noexcept { return v_.index() == 0; }
  [[nodiscard]] bool is_bool() const noexcept { return v_.index() == 1; }
  [[nodiscard]] bool is_number() const noexcept { return v_.index() == 2; }
  [[nodiscard]] bool is_string() const noexcept { return v_.index() == 3; }
  [[nodiscard]] bool is_array() const noexcept { return v_.index() == 4; }
  [[nodiscard]] bool is_object() const noexcept { return v_.index() == 5; }

  [[nodiscard]] bool as_bool() const { return get<bool>("a boolean"); }
  [[nodiscard]] double as_number() const { return get<double>("a number"); }
  [[nodiscard]] const std::string& as_string() const { return get<std::string>("a string"); }
  [[nodiscard]] const Array& as_array() const { return get<Array>("an array"); }
  [[nodiscard]] const Object& as_object() const { return get<Object>("an object"); }

  /// Appends \p value to this array.
  Json& push_back(Json value) {
    std::get<Array>(v_).push_back(std::move(value));
    return *this;
  }
  /// Sets key \p key of this object (replacing an existing one) and returns the value.
  Json& set(std::string_view key, Json value) {
    Object& o = std::get<Object>(v_);
    for (auto& [k, v] : o)
      if (k == key) return v = std::move(value);
    o.emplace_back(std::string(key), std::move(value));
    return o.back().second;
  }
  /// True if this is an object with key \p key.
  [[nodiscard]] bool contains(std::string_view key) const {
    if (!is_object()) return false;
    for (const auto& [k, v] : as_object())
      if (k == key) return true;
    return false;
  }
  /// The value at \p key of this object; throws std::out_of_range if it is missing.
  [[nodiscard]] const Json& at(std::string_view key) const {
    for (const auto& [k, v] : as_object())
      if (k == key) return v;
    throw std::out_of_range("json: no key \"" + std::string(key) + "\"");
  }

  /// The value as JSON text; \p indent spaces per level (0: one line). Non-finite numbers are
  /// written as null, since JSON has no NaN.
  [[nodiscard]] std::string dump(int indent = 2) const {
    std::string out;
    write(out, indent, 0);
    return out;
  }

  /// Parses JSON text. Throws topograsp::invalid_argument naming "json" with the offset of the
  /// first error.
  [[nodiscard]] static Json parse(std::string_view text) {
    std::size_t i = 0;
    Json v = parse_value(text, i, 0);
    skip_space(text, i);
    if (i != text.size()) fail(i, "trailing characters");
    return v;
  }

 private:
  template <class T>
  const T& get(const char* what) const {
    if (const T* p = std::get_if<T>(&v_)) return *p;
    throw std::logic_error(std::string("json: the value is not ") + what);
  }

  static void write_string(std::string& out, std::string_view s) {
    out += '"';
    for (const char c : s) {
      switch (c) {
        case '"':
          out += "\\\"";
          break;
        case '\\':
          out += "\\\\";
          break;
        case '\n':
          out += "\\n";
          break;
        case '\t':
          out += "\\t";
          break;
        case '\r':
          out += "\\r";
          break;
        default:
          if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
            out += buf;
          } else {
            out += c;
          }
      }
    }
    out += '"';
  }

  void write(std::string& out, int indent, int level) const {
    const auto newline = [&](int l) {
      if (indent <= 0) return;
      out += '\n';
      out.append(static_cast<std::size_t>(indent * l), ' ');
    };
    switch (v_.index()) {
      case 0:
        out += "null";
        break;
      case 1:
        out += std::get<bool>(v_) ? "true" : "false";
        break;
      case 2: {
        const double d = std::get<double>(v_);
        if (!std::isfinite(d)) {
          out += "null";
        } else if (d == std::floor(d) && std::abs(d) < 1e15) {
          out += std::to_string(static_cast<long long>(d));
        } else {
          char buf[32];
          std::snprintf(buf, sizeof buf, "%.10g", d);
          out += buf;
        }
        break;
      }
      case 3:
        write_string(out, std::get<std::string>(v_));
        break;
      case 4: {
        const Array& a = std::get<Array>(v_);
        out += '[';
        for (std::size_t k = 0; k < a.size(); ++k) {
          if (k) out += ',';
          newline(level + 1);
          a[k].write(out, indent, level + 1);
        }
        if (!a.empty()) newline(level);
        out += ']';
        break;
      }
      default: {
        const Object& o = std::get<Object>(v_);
        out += '{';
        for (std::size_t k = 0; k < o.size(); ++k) {
          if (k) out += ',';
          newline(level + 1);
          write_string(out, o[k].first);
          out += indent > 0 ? ": " : ":";
          o[k].second.write(out, indent, level + 1);
        }
        if (!o.empty()) newline(level);
        out += '}';
      }
    }
  }

  [[noreturn]] static void fail(std::size_t at, const char* what) {
    detail::throw_invalid_argument("json", std::string(what) + " at offset " + std::to_string(at));
  }
  static void skip_space(std::string_view t, std::size_t& i) {
    while (i < t.size() && (t[i] == ' ' || t[i] == '\n' || t[i] == '\t' || t[i] == '\r')) ++i;
  }
  static bool consume(std::string_view t, std::size_t& i, std::string_view word) {
    if (t.substr(i, word.size()) != word) return false;
    i += word.size();
    return true;
  }
  static std::string parse_string(std::string_view t, std::size_t& i) {
    if (i >= t.size() || t[i] != '"') fail(i, "expected a string");
    ++i;
    std::string s;
    while (i < t.size() && t[i] != '"') {
      if (t[i] == '\\') {
        if (++i >= t.size()) break;
        switch (t[i]) {
          case 'n':
            s += '\n';
            break;
          case 't':
            s += '\t';
            break;
          case 'r':
            s += '\r';
            break;
          case 'b':
            s += '\b';
            break;
          case 'f':
            s += '\f';
            break;
          case 'u': {
            if (i + 4 >= t.size()) fail(i, "bad \\u escape");
            const unsigned code =
                static_cast<unsigned>(std::stoul(std::string(t.substr(i + 1, 4)), nullptr, 16));
            if (code < 0x80)
              s += static_cast<char>(code);
            else
              s += '?';  // only ASCII escapes are produced by the writer
            i += 4;
            break;
          }
          default:
            s += t[i];
        }
        ++i;
      } else {
        s += t[i++];
      }
    }
    if (i >= t.size()) fail(i, "unterminated string");
    ++i;
    return s;
  }
  static Json parse_value(std::string_view t, std::size_t& i, int depth) {
    if (depth > 256) fail(i, "nesting too deep");
    skip_space(t, i);
    if (i >= t.size()) fail(i, "unexpected end");
    const char c = t[i];
    if (c == '{') {
      ++i;
      Json o = object();
      skip_space(t, i);
      if (i < t.size() && t[i] == '}') return ++i, o;
      while (true) {
        skip_space(t, i);
        std::string key = parse_string(t, i);
        skip_space(t, i);
        if (i >= t.size() || t[i] != ':') fail(i, "expected ':'");
        ++i;
        o.set(key, parse_value(t, i, depth + 1));
        skip_space(t, i);
        if (i < t.size() && t[i] == ',') {
          ++i;
          continue;
        }
        if (i < t.size() && t[i] == '}') return ++i, o;
        fail(i, "expected ',' or '}'");
      }
    }
    if (c == '[') {
      ++i;
      Json a = array();
      skip_space(t, i);
      if (i < t.size() && t[i] == ']') return ++i, a;
      while (true) {
        a.push_back(parse_value(t, i, depth + 1));
        skip_space(t, i);
        if (i < t.size() && t[i] == ',') {
          ++i;
          continue;
        }
        if (i < t.size() && t[i] == ']') return ++i, a;
        fail(i, "expected ',' or ']'");
      }
    }
    if (c == '"') return Json(parse_string(t, i));
    if (consume(t, i, "true")) return Json(true);
    if (consume(t, i, "false")) return Json(false);
    if (consume(t, i, "null")) return Json();
    const std::size_t start = i;
    while (i < t.size() && (std::isdigit(static_cast<unsigned char>(t[i])) || t[i] == '-' ||
                            t[i] == '+' || t[i] == '.' || t[i] == 'e' || t[i] == 'E'))
      ++i;
    if (start == i) fail(i, "unexpected character");
    const std::string number(t.substr(start, i - start));
    std::size_t used = 0;
    double d = 0.0;
    try {
      d = std::stod(number, &used);
    } catch (const std::exception&) {
      fail(start, "bad number");
    }
    if (used != number.size()) fail(start, "bad number");
    return Json(d);
  }

  std::variant<std::nullptr_t, bool, double, std::string, Array, Object> v_{nullptr};
};

}  // namespace topograsp
