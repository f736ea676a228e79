// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The tree parse_xml() reads (XmlDocument: elements with their attributes, text and lines) and
/// its error, xml_error.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <topograsp/core/error.hpp>

namespace topograsp {

/// The deepest nesting of elements parse_xml() accepts, the root element being level 1 (robot
/// models nest fewer than 20 levels; MJCF's body tree is the deepest).
inline constexpr int k_xml_max_depth = 256;

/// One attribute of an element: its name and its value with entities and references decoded.
struct XmlAttribute {
  std::string name;
  std::string value;
};

/// One element: its name, attributes, child elements and text.
struct XmlElement {
  std::string name;
  /// The attributes in document order (their names are distinct).
  std::vector<XmlAttribute> attributes;
  /// The child elements, in document order (elements only: no text or comment nodes).
  std::vector<XmlElement> children;
  /// The character data directly inside this element, concatenated (with the whitespace between
  /// its children, CDATA sections included), entities decoded, line ends normalised, not trimmed.
  std::string text;
  /// The 1-based line of the '<' of the start tag.
  int line = 0;

  /// The value of the attribute named \p key, or nullptr if there is none.
  [[nodiscard]] const std::string* attribute(std::string_view key) const noexcept {
    for (const XmlAttribute& a : attributes)
      if (a.name == key) return &a.value;
    return nullptr;
  }
  /// Whether the element has an attribute named \p key.
  [[nodiscard]] bool has(std::string_view key) const noexcept { return attribute(key) != nullptr; }
};

/// A parsed XML document: the name of its file (for messages) and its root element.
struct XmlDocument {
  std::string file;
  XmlElement root;
};

/// The error of parse_xml() and read_xml_file(): what() is "FILE:LINE: problem" (or "FILE:
/// problem" when line() is 0, for a file that cannot be opened or read).
class xml_error : public invalid_argument {
 public:
  xml_error(std::string file, int line, std::string problem)
      : invalid_argument(detail::file_line_message(file, line, problem)),
        file_(std::move(file)),
        problem_(std::move(problem)),
        line_(line) {}

  /// The file name given to parse_xml() (the path for read_xml_file()).
  [[nodiscard]] const std::string& file() const noexcept { return file_; }
  /// The 1-based line of the problem; 0 if it is not at a line.
  [[nodiscard]] int line() const noexcept { return line_; }
  /// The problem, without the file and line.
  [[nodiscard]] const std::string& problem() const noexcept { return problem_; }

 private:
  std::string file_;
  std::string problem_;
  int line_;
};

}  // namespace topograsp
