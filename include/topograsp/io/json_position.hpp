// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Where a field is written in a JSON text: json_field_line() gives the line of a field named by
/// a path such as "fingers[1].points[0]" or "joints.wrist.hold", so that an error about a file
/// read into a Json (which keeps no positions) can name the line as well as the field.
#pragma once

#include <cctype>
#include <cstddef>
#include <string>
#include <string_view>

namespace topograsp {

namespace detail {

// A scanner over a JSON text that follows a field path through it, counting lines. It trusts the
// text to be JSON (Json::parse read it first) and gives up, keeping the deepest line found, where
// it is not.
class JsonFieldScanner {
 public:
  explicit JsonFieldScanner(std::string_view text) : text_(text) {}

  // The line (1-based) of the value at path in the text, or of the deepest part of the path that
  // is in it (the enclosing object's or array's first line for a member that is missing).
  int line_of(std::string_view path) {
    skip_space();
    int found = line_;
    while (at_ < text_.size()) {
      if (path.empty()) return found;
      const char c = text_[at_];
      if (c == '{') {
        if (path.front() == '.') path.remove_prefix(1);
        if (!enter_member(path)) return found;
      } else if (c == '[') {
        if (!enter_element(path)) return found;
      } else {
        return found;  // a scalar cannot hold the rest of the path
      }
      found = line_;
    }
    return found;
  }

 private:
  std::string_view text_;
  std::size_t at_ = 0;
  int line_ = 1;

  void skip_space() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) {
      if (text_[at_] == '\n') ++line_;
      ++at_;
    }
  }

  // The string at at_ (a quote), decoded but for \u escapes (kept as written); at_ past it.
  std::string read_string() {
    std::string out;
    ++at_;
    while (at_ < text_.size() && text_[at_] != '"') {
      if (text_[at_] == '\\' && at_ + 1 < text_.size()) {
        ++at_;
        const char e = text_[at_];
        if (e == 'u')
          out += "\\u";  // the four hex digits follow as written
        else
          out += e == 'n'   ? '\n'
                 : e == 't' ? '\t'
                 : e == 'r' ? '\r'
                 : e == 'b' ? '\b'
                 : e == 'f' ? '\f'
                            : e;
      } else {
        out += text_[at_];
      }
      ++at_;
    }
    ++at_;
    return out;
  }

  // Skips one value (at at_), counting its lines.
  void skip_value() {
    int depth = 0;
    do {
      if (at_ >= text_.size()) return;
      const char c = text_[at_];
      if (c == '"') {
        (void)read_string();
      } else {
        if (c == '{' || c == '[') ++depth;
        if (c == '}' || c == ']') --depth;
        ++at_;
        if (depth == 0 && c != '{' && c != '[' && c != '}' && c != ']')
          while (at_ < text_.size() && text_[at_] != ',' && text_[at_] != '}' &&
                 text_[at_] != ']' && !std::isspace(static_cast<unsigned char>(text_[at_])))
            ++at_;
      }
      skip_space();
    } while (depth > 0);
  }

  // In the object at at_: moves to the value of the first member whose key the path starts with
  // (followed by '.', '[' or the path's end) and takes the key off the path.
  bool enter_member(std::string_view& path) {
    ++at_;
    skip_space();
    while (at_ < text_.size() && text_[at_] == '"') {
      const std::string key = read_string();
      skip_space();
      ++at_;  // ':'
      skip_space();
      const bool match =
          path.starts_with(key) &&
          (path.size() == key.size() || path[key.size()] == '.' || path[key.size()] == '[');
      if (match) {
        path.remove_prefix(key.size());
        return true;
      }
      skip_value();
      if (at_ < text_.size() && text_[at_] == ',') ++at_;
      skip_space();
    }
    return false;
  }

  // In the array at at_: moves to the element the path's "[i]" names and takes it off the path.
  bool enter_element(std::string_view& path) {
    if (path.empty() || path.front() != '[') return false;
    std::size_t index = 0, i = 1;
    while (i < path.size() && std::isdigit(static_cast<unsigned char>(path[i])))
      index = index * 10 + static_cast<std::size_t>(path[i++] - '0');
    if (i == 1 || i >= path.size() || path[i] != ']') return false;
    path.remove_prefix(i + 1);
    ++at_;
    skip_space();
    for (std::size_t k = 0; k < index; ++k) {
      if (at_ >= text_.size() || text_[at_] == ']') return false;
      skip_value();
      if (at_ < text_.size() && text_[at_] == ',') ++at_;
      skip_space();
    }
    return at_ < text_.size() && text_[at_] != ']';
  }
};

}  // namespace detail

/// The line (1-based) in the JSON \p text where the field \p path is written: members by name,
/// separated by '.', array elements by "[i]" ("fingers[1].points[0]", "joints.wrist.hold"; "" is
/// the document). For a path that is not all in the text, the line of its deepest part that is
/// (the line that opens the object a missing member belongs in). A member is the first, in the
/// order written, whose key the path starts with, followed by '.', '[' or the path's end (so a
/// key may contain '.'). \p text is expected to be JSON (parsed already); on other text the line
/// is where the scan stopped.
[[nodiscard]] inline int json_field_line(std::string_view text, std::string_view path) {
  return detail::JsonFieldScanner(text).line_of(path);
}

}  // namespace topograsp
