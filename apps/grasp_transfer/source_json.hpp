// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// A SourceGrasp as JSON (results.json's "source_grasp" of each planned transfer,
/// data/schemas/results.schema.json), written so that reading it back gives the same numbers to
/// the last bit: frames as a position and a row-major rotation matrix (not a quaternion), every
/// number in the shortest text that reads back as the same double (Json::dump).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/grasp/transfer/source.hpp>
#include <topograsp/io/json.hpp>

namespace topograsp {

namespace detail {

// A vector's numbers as a JSON array (results.json's arrays of numbers).
inline Json json_vector(const auto& v) {
  // Built in place: moving number-holding Json temporaries into a vector trips GCC 12's
  // -Wmaybe-uninitialized on std::variant.
  Json::Array a;
  a.reserve(static_cast<std::size_t>(v.size()));
  for (Eigen::Index i = 0; i < v.size(); ++i) a.emplace_back(static_cast<double>(v[i]));
  return Json(std::move(a));
}

// A rotation matrix, row by row.
inline Json source_rotation(const Eigen::Matrix3d& R) {
  Json::Array a;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a.emplace_back(R(r, c));
  return Json(std::move(a));
}

inline Json source_frame(const Eigen::Isometry3d& T) {
  Json j = Json::object();
  j.set("position", json_vector(Vec3(T.translation())));
  j.set("rotation", source_rotation(T.linear()));
  return j;
}

// Reading: each error names the field's path below the source_grasp (`where`).
inline const Json& source_field(const Json& j, std::string_view key, const std::string& where) {
  if (!j.is_object() || !j.contains(key))
    throw_invalid_argument(where, "missing \"" + std::string(key) + "\"");
  return j.at(key);
}

inline double source_number(const Json& j, const std::string& where) {
  if (!j.is_number()) throw_invalid_argument(where, "expected a number");
  return j.as_number();
}

template <int N>
Vec<N> source_vector(const Json& j, const std::string& where) {
  if (!j.is_array() || j.as_array().size() != static_cast<std::size_t>(N))
    throw_invalid_argument(where, "expected an array of " + std::to_string(N) + " numbers");
  Vec<N> v;
  for (int i = 0; i < N; ++i)
    v[i] = source_number(j.as_array()[static_cast<std::size_t>(i)],
                         where + "[" + std::to_string(i) + "]");
  return v;
}

inline Eigen::Matrix3d source_rotation_of(const Json& j, const std::string& where) {
  const Vec<9> r = source_vector<9>(j, where);
  Eigen::Matrix3d R;
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) R(i, c) = r[3 * i + c];
  return R;
}

inline Eigen::Isometry3d source_frame_of(const Json& j, const std::string& where) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = source_vector<3>(source_field(j, "position", where), where + ".position");
  T.linear() = source_rotation_of(source_field(j, "rotation", where), where + ".rotation");
  return T;
}

inline const Json::Array& source_array(const Json& j, const std::string& where) {
  if (!j.is_array()) throw_invalid_argument(where, "expected an array");
  return j.as_array();
}

}  // namespace detail

/// \p s as JSON: {"hand", "root", "grasp_frame", "palm_frame" (each {"position": [x, y, z],
/// "rotation": [9 numbers, row by row]}), "curves": [[[x, y, z], ...], ...], "digits": [{"tip":
/// [x, y, z], "length"}, ...], "thumb", "palm": [{"type", "rotation", "position", "size"}, ...]}
/// (docs/transfer.md, "A robot hand as the demonstrator"). A source with a reason it is unusable
/// is not written (null).
[[nodiscard]] inline Json source_grasp_json(const SourceGrasp& s) {
  if (!s.unusable.empty()) return Json();
  Json j = Json::object();
  j.set("hand", s.hand);
  j.set("root", detail::source_frame(s.root));
  j.set("grasp_frame", detail::source_frame(s.grasp_frame));
  j.set("palm_frame", detail::source_frame(s.palm_frame));
  Json curves = Json::array();
  for (const std::vector<Vec3>& c : s.curves) {
    Json points = Json::array();
    for (const Vec3& p : c) points.push_back(detail::json_vector(p));
    curves.push_back(std::move(points));
  }
  j.set("curves", std::move(curves));
  Json digits = Json::array();
  for (const SourceDigit& d : s.digits) {
    Json digit = Json::object();
    digit.set("tip", detail::json_vector(d.tip));
    digit.set("length", d.length);
    digits.push_back(std::move(digit));
  }
  j.set("digits", std::move(digits));
  j.set("thumb", s.thumb);
  Json palm = Json::array();
  for (const Primitive& shape : s.palm) {
    Json p = Json::object();
    p.set("type", std::string(to_string(shape.type)));
    p.set("rotation", detail::source_rotation(shape.R));
    p.set("position", detail::json_vector(shape.p));
    p.set("size", detail::json_vector(shape.size));
    palm.push_back(std::move(p));
  }
  j.set("palm", std::move(palm));
  return j;
}

/// The SourceGrasp that source_grasp_json() wrote as \p j, to the last bit. \p where names \p j in
/// errors ("grasps[3].source_grasp").
/// \throws topograsp::invalid_argument naming the field (e.g.
/// "grasps[3].source_grasp.curves[1][4][2]") for a missing field, a value of the wrong type or
/// length, or an unknown shape type; naming
/// \p where for a grasp that unusable_source() refuses, with its reason.
[[nodiscard]] inline SourceGrasp source_grasp_of(const Json& j, const std::string& where) {
  using namespace detail;
  if (!j.is_object()) throw_invalid_argument(where, "expected an object");
  SourceGrasp s;
  const Json& hand = source_field(j, "hand", where);
  if (!hand.is_string()) throw_invalid_argument(where + ".hand", "expected a string");
  s.hand = hand.as_string();
  s.root = source_frame_of(source_field(j, "root", where), where + ".root");
  s.grasp_frame = source_frame_of(source_field(j, "grasp_frame", where), where + ".grasp_frame");
  s.palm_frame = source_frame_of(source_field(j, "palm_frame", where), where + ".palm_frame");
  const Json::Array& curves = source_array(source_field(j, "curves", where), where + ".curves");
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const std::string at = where + ".curves[" + std::to_string(c) + "]";
    std::vector<Vec3>& curve = s.curves.emplace_back();
    const Json::Array& points = source_array(curves[c], at);
    for (std::size_t k = 0; k < points.size(); ++k)
      curve.push_back(source_vector<3>(points[k], at + "[" + std::to_string(k) + "]"));
  }
  const Json::Array& digits = source_array(source_field(j, "digits", where), where + ".digits");
  for (std::size_t f = 0; f < digits.size(); ++f) {
    const std::string at = where + ".digits[" + std::to_string(f) + "]";
    s.digits.push_back({source_vector<3>(source_field(digits[f], "tip", at), at + ".tip"),
                        source_number(source_field(digits[f], "length", at), at + ".length")});
  }
  const double thumb = source_number(source_field(j, "thumb", where), where + ".thumb");
  if (!(thumb >= 0.0 && thumb < static_cast<double>(s.digits.size())) ||
      thumb != static_cast<double>(static_cast<int>(thumb)))
    throw_invalid_argument(where + ".thumb", "expected the index of one of the digits");
  s.thumb = static_cast<int>(thumb);
  const Json::Array& palm = source_array(source_field(j, "palm", where), where + ".palm");
  for (std::size_t k = 0; k < palm.size(); ++k) {
    const std::string at = where + ".palm[" + std::to_string(k) + "]";
    const Json& type = source_field(palm[k], "type", at);
    Primitive shape;
    bool known = false;
    for (const ShapeType t :
         {ShapeType::sphere, ShapeType::capsule, ShapeType::box, ShapeType::cylinder})
      if (type.is_string() && type.as_string() == to_string(t)) {
        shape.type = t;
        known = true;
      }
    if (!known) throw_invalid_argument(at + ".type", "expected sphere, capsule, box or cylinder");
    shape.R = source_rotation_of(source_field(palm[k], "rotation", at), at + ".rotation");
    shape.p = source_vector<3>(source_field(palm[k], "position", at), at + ".position");
    shape.size = source_vector<3>(source_field(palm[k], "size", at), at + ".size");
    s.palm.push_back(shape);
  }
  if (const std::string reason = unusable_source(s); !reason.empty())
    throw_invalid_argument(where, reason);
  return s;
}

}  // namespace topograsp
