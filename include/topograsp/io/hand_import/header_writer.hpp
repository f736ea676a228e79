// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// model_header(): an imported hand written as a C++ header of constexpr arrays for make_model().
#pragma once

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <Eigen/Geometry>

#include <topograsp/core/error.hpp>
#include <topograsp/io/hand_import/common.hpp>
#include <topograsp/io/hand_import/description.hpp>
#include <topograsp/model/spec.hpp>

namespace topograsp {
namespace detail {

// \p v in the shortest form that reads back exactly; \p clean: below 1e-15 written as 0 (the
// rounding noise of rotations, not a size).
inline void append_number(std::string& s, double v, bool clean = false) {
  if (clean && std::abs(v) < 1e-15) v = 0.0;
  char b[32];
  const auto [end, ec] = std::to_chars(b, b + sizeof b, v);
  std::string t(b, ec == std::errc() ? end : b);
  if (t.find_first_of(".en") == std::string::npos) t += ".0";
  s += t;
}

// The C++ code of pose p: at(x, y, z), with .quat(w, x, y, z) when it turns; a turn that takes
// each axis onto an axis (every entry of its matrix -1, 0 or 1) as Pose{{matrix}, {x, y, z}},
// which keeps it exact (a quarter turn's quaternion has 1/sqrt(2) in it, and its matrix would
// not have exact zeros).
inline std::string pose_code(const Pose& p) {
  const bool axes_onto_axes = std::all_of(
      p.R.begin(), p.R.end(), [](double r) { return r == 0.0 || r == 1.0 || r == -1.0; });
  const bool turns = p.R != Pose{}.R;
  std::string s = axes_onto_axes && turns ? "Pose{{" : "at(";
  if (axes_onto_axes && turns) {
    for (std::size_t i = 0; i < 9; ++i)
      s += std::string(p.R[i] == 0.0 ? "0" : p.R[i] > 0.0 ? "1" : "-1") + (i < 8 ? ", " : "}, {");
    for (std::size_t i = 0; i < 3; ++i) {
      append_number(s, p.p[i], true);
      s += i < 2 ? ", " : "}}";
    }
    return s;
  }
  for (std::size_t i = 0; i < 3; ++i) {
    append_number(s, p.p[i], true);
    s += i < 2 ? ", " : ")";
  }
  const Eigen::Isometry3d T = p.isometry();
  if (!T.linear().isIdentity(1e-15)) {
    Eigen::Quaterniond q(T.linear());
    if (q.w() < 0.0) q.coeffs() *= -1.0;
    s += ".quat(";
    const double c[4] = {q.w(), q.x(), q.y(), q.z()};
    for (int i = 0; i < 4; ++i) {
      append_number(s, c[i], true);
      s += i < 3 ? ", " : ")";
    }
  }
  return s;
}

// The C++ code of v: {x, y, z}.
inline std::string triple_code(const std::array<double, 3>& v) {
  std::string s = "{";
  for (std::size_t i = 0; i < 3; ++i) {
    append_number(s, v[i]);
    s += i < 2 ? ", " : "}";
  }
  return s;
}

// Where header_text() puts a text: in a // comment or between the quotes of a string literal.
enum class HeaderText : std::uint8_t { comment, string };

// The one way text from the user or the file (comments, file names, paths, names) enters a
// generated header: nothing in it can end the comment or the line it is on, or the string literal.
// A control character (below 0x20, and 0x7f: CR and LF end a line) is written as \ooo (octal),
// or, with \p refuse_as, refused: invalid_argument naming \p refuse_as, the character's code and
// its position. In a string literal " and \ are escaped (\" and \\); in a comment a backslash
// at the end is written \134 (a backslash before the line's end would join the next line to the
// comment). The header has only // comments, so "*/" needs nothing.
inline std::string header_text(std::string_view text, HeaderText where,
                               std::string_view refuse_as = {}) {
  std::string s;
  s.reserve(text.size());
  const auto octal = [&s](unsigned char c) {
    s += '\\';
    for (int shift = 6; shift >= 0; shift -= 3) s += static_cast<char>('0' + ((c >> shift) & 7));
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) {
      if (!refuse_as.empty())
        throw_invalid_argument(refuse_as, "a control character (code " + std::to_string(c) +
                                              ") at position " + std::to_string(i) + " of \"" +
                                              header_text(text, HeaderText::string) +
                                              "\": it would end the comment's line");
      octal(c);
    } else if (where == HeaderText::string && (c == '"' || c == '\\')) {
      s += '\\';
      s += static_cast<char>(c);
    } else if (where == HeaderText::comment && c == '\\' && i + 1 == text.size()) {
      octal(c);
    } else {
      s += static_cast<char>(c);
    }
  }
  return s;
}

}  // namespace detail

/// The C++ header that declares \p hand's links, shapes and frames as constexpr arrays in
/// namespace \p ns (`links`, `shapes`, `frames`, for make_model()), with \p comments (one line
/// each: where the file comes from, its licence), the joint names and the import's notes as
/// comments; with \p description (describe_hand(), applied to \p hand) also `model`, the hand
/// it describes, made by make_model(). Names, the file's name and paths are written through
/// detail::header_text() (control characters escaped), so the header always compiles.
/// \throws topograsp::invalid_argument naming "ns" if \p ns is not a C++ namespace name
/// (identifiers joined by ::), naming "comments" if a comment has a control character (a line
/// break would end the comment).
[[nodiscard]] inline std::string model_header(const ImportedHand& hand, std::string_view ns,
                                              const std::vector<std::string>& comments = {},
                                              const HandDescription* description = nullptr) {
  bool ok = !ns.empty();
  for (std::size_t i = 0, start = 0; ok && i <= ns.size(); ++i) {
    if (i < ns.size() && ns[i] != ':') continue;
    const std::string_view id = ns.substr(start, i - start);
    ok = !id.empty() && !std::isdigit(static_cast<unsigned char>(id[0])) &&
         std::all_of(id.begin(), id.end(), [](char c) {
           return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
         });
    if (i < ns.size()) {
      ok = ok && i + 1 < ns.size() && ns[i + 1] == ':';
      start = i + 2;
      ++i;
    }
  }
  static constexpr std::array<std::string_view, 97> keywords{"alignas",
                                                             "alignof",
                                                             "and",
                                                             "and_eq",
                                                             "asm",
                                                             "auto",
                                                             "bitand",
                                                             "bitor",
                                                             "bool",
                                                             "break",
                                                             "case",
                                                             "catch",
                                                             "char",
                                                             "char8_t",
                                                             "char16_t",
                                                             "char32_t",
                                                             "class",
                                                             "compl",
                                                             "concept",
                                                             "const",
                                                             "consteval",
                                                             "constexpr",
                                                             "constinit",
                                                             "const_cast",
                                                             "continue",
                                                             "co_await",
                                                             "co_return",
                                                             "co_yield",
                                                             "decltype",
                                                             "default",
                                                             "delete",
                                                             "do",
                                                             "double",
                                                             "dynamic_cast",
                                                             "else",
                                                             "enum",
                                                             "explicit",
                                                             "export",
                                                             "extern",
                                                             "false",
                                                             "float",
                                                             "for",
                                                             "friend",
                                                             "goto",
                                                             "if",
                                                             "inline",
                                                             "int",
                                                             "long",
                                                             "mutable",
                                                             "namespace",
                                                             "new",
                                                             "noexcept",
                                                             "not",
                                                             "not_eq",
                                                             "nullptr",
                                                             "operator",
                                                             "or",
                                                             "or_eq",
                                                             "private",
                                                             "protected",
                                                             "public",
                                                             "register",
                                                             "reinterpret_cast",
                                                             "requires",
                                                             "return",
                                                             "short",
                                                             "signed",
                                                             "sizeof",
                                                             "static",
                                                             "static_assert",
                                                             "static_cast",
                                                             "struct",
                                                             "switch",
                                                             "template",
                                                             "this",
                                                             "thread_local",
                                                             "throw",
                                                             "true",
                                                             "try",
                                                             "typedef",
                                                             "typeid",
                                                             "typename",
                                                             "union",
                                                             "unsigned",
                                                             "using",
                                                             "virtual",
                                                             "void",
                                                             "volatile",
                                                             "wchar_t",
                                                             "while",
                                                             "xor",
                                                             "xor_eq",
                                                             "final",
                                                             "override",
                                                             "import",
                                                             "module",
                                                             "std"};
  for (std::size_t i = 0, start = 0; ok && i <= ns.size(); ++i)
    if (i == ns.size() || ns[i] == ':') {
      const std::string_view id = ns.substr(start, i - start);
      ok = std::find(keywords.begin(), keywords.end(), id) == keywords.end();
      start = i + 2;
      ++i;
    }
  if (!ok)
    detail::throw_invalid_argument(
        "ns", "\"" + std::string(ns) + "\" is not a C++ namespace name (a::b)");
  using detail::append_number;
  using detail::header_text;
  using detail::HeaderText;
  using detail::pose_code;
  using detail::triple_code;
  const auto quoted = [](const Name& n) {
    return '"' + header_text(n.view(), HeaderText::string) + '"';
  };
  // Generated code keeps the tool's layout: clang-format would join the comment lines.
  std::string s = "// clang-format off\n";
  for (const std::string& c : comments)
    s += "// " + header_text(c, HeaderText::comment, "comments") + "\n";
  const std::string file =
      header_text(std::filesystem::path(hand.source).filename().string(), HeaderText::comment);
  s += "// Generated by topograsp_import_hand from " + file + " (" +
       std::string(to_string(hand.format)) + "). Do not edit: edit the file and import it again.\n";
  for (const std::string& n : hand.notes)
    s += "// Note: " + header_text(n, HeaderText::comment) + "\n";
  s += std::string("#pragma once\n\n#include <topograsp/model/") +
       (description != nullptr ? "model.hpp" : "spec.hpp") + ">\n\nnamespace " + std::string(ns) +
       " {\n\nusing namespace topograsp;\n\n";
  s += "/// The links of " + file + ", parents first; each moving link carries its joint.\n";
  s += "inline constexpr auto links = topograsp::links(";
  for (std::size_t i = 0; i < hand.links.size(); ++i) {
    const LinkSpec& l = hand.links[i];
    s += i == 0 ? "\n    " : ",\n    ";
    if (!hand.joint_names[i].empty() && hand.joint_names[i] != l.name.view())
      s += "// joint " + header_text(hand.joint_names[i], HeaderText::comment) + "\n    ";
    if (l.parent.empty()) {
      s += "root(" + quoted(l.name) + ")";
    } else if (l.type == JointType::fixed) {
      s += "fixed(" + quoted(l.name) + ", " + quoted(l.parent) + ", " + pose_code(l.origin) + ")";
    } else {
      s += std::string(l.type == JointType::revolute ? "revolute(" : "prismatic(") +
           quoted(l.name) + ", " + quoted(l.parent) + ", " + pose_code(l.origin) + ", " +
           triple_code(l.axis) + ", ";
      append_number(s, l.lower);
      s += ", ";
      append_number(s, l.upper);
      s += ")";
    }
    if (!l.mimic.empty()) {
      s += ".mimics(" + quoted(l.mimic) + ", ";
      append_number(s, l.multiplier);
      s += ", ";
      append_number(s, l.offset);
      s += ")";
    }
    if (l.effort != 0.0 || l.velocity != 0.0 || l.armature != 0.0) {
      s += ".actuator(";
      append_number(s, l.effort);
      s += ", ";
      append_number(s, l.velocity);
      s += ", ";
      append_number(s, l.armature);
      s += ")";
    }
    if (l.closing != 0.0) {  // from a hand description: the file cannot say it
      s += ".closes(";
      append_number(s, l.closing);
      s += ")";
    }
    if (l.mass != 0.0) {
      s += ".inertial(";
      append_number(s, l.mass);
      s += ", " + triple_code(l.com) + ")";
    }
  }
  s += ");\n\n/// Their collision shapes.\ninline constexpr auto shapes = topograsp::shapes(";
  for (std::size_t i = 0; i < hand.shapes.size(); ++i) {
    const ShapeSpec& sh = hand.shapes[i];
    s += i == 0 ? "\n    " : ",\n    ";
    s += "ShapeSpec{" + quoted(sh.link) + ", ShapeType::" + std::string(to_string(sh.type)) + ", " +
         pose_code(sh.pose) + ", " + triple_code(sh.size) + "}";
  }
  s += ");\n\n/// The file's named frames (MJCF sites).\ninline constexpr auto frames = "
       "topograsp::frames(";
  for (std::size_t i = 0; i < hand.frames.size(); ++i) {
    const FrameSpec& f = hand.frames[i];
    s += i == 0 ? "\n    " : ",\n    ";
    s += "frame(" + quoted(f.name) + ", " + quoted(f.link) + ", " + pose_code(f.offset) + ")";
  }
  s += ");\n";
  if (description != nullptr) {
    const auto text = [](const std::string& n) {
      return '"' + header_text(n, HeaderText::string) + '"';
    };
    const auto chain = [&](const char* kind, const HandChain& c) {
      std::string out = std::string(kind) + "(" + text(c.name) + ", {";
      for (std::size_t i = 0; i < c.points.size(); ++i)
        out += (i == 0 ? "" : ", ") + text(c.points[i]);
      return out + "})";
    };
    s += "\n/// The hand that " +
         header_text(std::filesystem::path(description->source).filename().string(),
                     HeaderText::comment) +
         " describes: checked by make_model() while it compiles.\ninline constexpr auto model = "
         "make_model(\n    " +
         text(description->name) + ", links, shapes, frames,\n    hand(" +
         text(description->palm_centre);
    for (const HandChain& f : description->fingers) s += ",\n         " + chain("finger", f);
    s += ",\n         " + chain("thumb", description->thumb) + "));\n";
  }
  s += "\n}  // namespace " + std::string(ns) + "\n";
  return s;
}

}  // namespace topograsp
