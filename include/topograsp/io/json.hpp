// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Json: a small JSON value with a writer and a strict reader, enough for results files and the
/// tests that check their schema. Objects keep their keys in insertion order.
#pragma once

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <variant>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/io/detail/utf8.hpp>

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

  /// The value as JSON text; \p indent spaces per level (0: one line). A number is written as
  /// the shortest text that parses back to the same double (integers below 1e15 without a
  /// fraction); non-finite numbers are written as null, since JSON has no NaN.
  [[nodiscard]] std::string dump(int indent = 2) const {
    std::string out;
    write(out, indent, 0);
    return out;
  }

  /// The deepest nesting of arrays and objects parse() accepts (it recurses once per level, so
  /// the limit bounds its stack use; results files nest 5 levels).
  static constexpr int k_max_depth = 256;

  /// Parses JSON text (RFC 8259, strictly). Throws topograsp::invalid_argument naming "json" with
  /// the byte offset of the first error, and never another exception (except std::bad_alloc):
  /// malformed syntax, a number outside JSON's grammar ("01", "1.", ".5", "+1") or above the
  /// double range (1.8e308; smaller than 4.9e-324 rounds to 0), a string with a raw control
  /// character, an unknown escape, a \u escape without exactly 4 hex digits or with an unpaired
  /// surrogate (pairs are decoded; every \u escape becomes UTF-8), or nesting deeper than
  /// k_max_depth. A repeated key keeps its last value.
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
        } else if (d == 0.0 && std::signbit(d)) {
          out += "-0";  // the sign of a zero reads back
        } else if (d == std::floor(d) && std::abs(d) < 1e15) {
          out += std::to_string(static_cast<long long>(d));
        } else {
          // The shortest text that reads back as the same double (std::to_chars without a
          // precision), so a dumped document re-parses to equal numbers.
          char buf[32];
          const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, d);
          out.append(buf, ec == std::errc() ? end : buf);
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
  // Exactly four hex digits at t[i..i+4): their value, or fail naming the offset.
  static unsigned parse_hex4(std::string_view t, std::size_t i) {
    if (t.size() < 4 || i > t.size() - 4) fail(i, "bad \\u escape (expected 4 hex digits)");
    unsigned code = 0;
    for (std::size_t k = i; k < i + 4; ++k) {
      const char c = t[k];
      unsigned d = 0;
      if (c >= '0' && c <= '9')
        d = static_cast<unsigned>(c - '0');
      else if (c >= 'a' && c <= 'f')
        d = static_cast<unsigned>(c - 'a') + 10u;
      else if (c >= 'A' && c <= 'F')
        d = static_cast<unsigned>(c - 'A') + 10u;
      else
        fail(k, "bad \\u escape (expected 4 hex digits)");
      code = code * 16u + d;
    }
    return code;
  }
  static std::string parse_string(std::string_view t, std::size_t& i) {
    if (i >= t.size() || t[i] != '"') fail(i, "expected a string");
    ++i;
    std::string s;
    while (i < t.size() && t[i] != '"') {
      if (static_cast<unsigned char>(t[i]) < 0x20)
        fail(i, "unescaped control character in a string");
      if (t[i] != '\\') {
        s += t[i++];
        continue;
      }
      const std::size_t escape = i;
      if (++i >= t.size()) break;
      switch (t[i]) {
        case '"':
        case '\\':
        case '/':
          s += t[i];
          break;
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
          unsigned cp = parse_hex4(t, i + 1);
          i += 4;
          if (cp >= 0xDC00u && cp <= 0xDFFFu) fail(escape, "lone low surrogate in \\u escape");
          if (cp >= 0xD800u && cp <= 0xDBFFu) {
            // A high surrogate must be followed by an escaped low surrogate.
            if (i + 2 >= t.size() || t[i + 1] != '\\' || t[i + 2] != 'u')
              fail(escape, "high surrogate in \\u escape without a low surrogate");
            const unsigned low = parse_hex4(t, i + 3);
            if (low < 0xDC00u || low > 0xDFFFu)
              fail(i + 1, "high surrogate in \\u escape without a low surrogate");
            cp = 0x10000u + ((cp - 0xD800u) << 10) + (low - 0xDC00u);
            i += 6;
          }
          detail::append_utf8(s, cp);
          break;
        }
        default:
          fail(escape, "bad escape (expected one of \\\" \\\\ \\/ \\b \\f \\n \\r \\t \\u)");
      }
      ++i;
    }
    if (i >= t.size()) fail(i, "unterminated string");
    ++i;
    return s;
  }
  // A number in JSON's grammar: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
  static Json parse_number(std::string_view t, std::size_t& i) {
    const std::size_t start = i;
    auto digits = [&] {
      const std::size_t from = i;
      while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
      return i - from;
    };
    if (i < t.size() && t[i] == '-') ++i;
    const std::size_t int_start = i;
    const std::size_t n_int = digits();
    if (n_int == 0) fail(start, "unexpected character");
    if (n_int > 1 && t[int_start] == '0') fail(start, "bad number (leading zero)");
    std::size_t n_frac = 0;
    if (i < t.size() && t[i] == '.') {
      ++i;
      n_frac = digits();
      if (n_frac == 0) fail(start, "bad number (no digit after '.')");
    }
    long long exponent = 0;
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
      ++i;
      bool negative = false;
      if (i < t.size() && (t[i] == '+' || t[i] == '-')) negative = t[i++] == '-';
      const std::size_t exp_start = i;
      if (digits() == 0) fail(start, "bad number (no digit in the exponent)");
      for (std::size_t k = exp_start; k < i; ++k)  // saturates: only its sign and size matter
        exponent = std::min(exponent * 10 + (t[k] - '0'), 1000000000LL);
      if (negative) exponent = -exponent;
    }
    double d = 0.0;
    const auto [end, ec] = std::from_chars(t.data() + start, t.data() + i, d);
    if (ec == std::errc::result_out_of_range) {
      // Overflow or total underflow: tell them apart by the decimal order of magnitude.
      const std::string_view mantissa = t.substr(int_start, n_int + (n_frac > 0 ? n_frac + 1 : 0));
      long long order = static_cast<long long>(n_int);
      for (const char c : mantissa) {
        if (c == '.') continue;
        if (c != '0') break;
        --order;
      }
      if (order + exponent > 0) fail(start, "number out of the double range (above 1.8e308)");
      d = t[start] == '-' ? -0.0 : 0.0;  // below 4.9e-324: rounds to zero
    } else if (ec != std::errc() || end != t.data() + i) {
      fail(start, "bad number");
    }
    return Json(d);
  }
  static Json parse_value(std::string_view t, std::size_t& i, int depth) {
    skip_space(t, i);
    if (i >= t.size()) fail(i, "unexpected end");
    const char c = t[i];
    if ((c == '{' || c == '[') && depth >= k_max_depth)
      fail(i, "nesting deeper than 256 arrays and objects");
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
    if (c == '-' || (c >= '0' && c <= '9')) return parse_number(t, i);
    fail(i, "unexpected character");
  }

  std::variant<std::nullptr_t, bool, double, std::string, Array, Object> v_{nullptr};
};

}  // namespace topograsp
