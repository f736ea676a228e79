// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: parse_keypoint_grasp (io/keypoint_grasp.hpp) on any bytes.
//
// - Only topograsp::keypoint_error may escape parse_keypoint_grasp() (its documented error);
//   anything else (the JSON reader's invalid_argument unwrapped, std::out_of_range, ...) is a
//   failure. Its what() starts with the file name given and ": ".
// - A parsed grasp has a non-empty object name and 21 finite keypoints.
// - keypoint_grasp_json() writes it to text that parses back to the same object name and the same
//   keypoints bit for bit (the header promises the numbers to the last bit).
// - keypoint_windings(g, 0) gives four windings, each finite and in [0, 4] (a curve of 9 points
//   adds at most 8 angles of pi); for keypoints all below 1e6 in magnitude it must not throw, for
//   larger ones it may throw topograsp::invalid_argument (the palm centre or a difference X_i - p
//   overflows).

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>
#include <typeinfo>

#include <topograsp/core/error.hpp>
#include <topograsp/io/keypoint_grasp.hpp>

#include "fuzz_input.hpp"

namespace {

using topograsp::KeypointGrasp;
using topograsp::Vec3;
using topograsp::fuzz::c_literal;
using topograsp::fuzz::fuzz_fail;
using topograsp::fuzz::num;
using topograsp::fuzz::vec_str;

constexpr std::string_view k_file = "fuzz.json";

bool same_bits(const Vec3& a, const Vec3& b) {
  for (int k = 0; k < 3; ++k)
    if (std::bit_cast<std::uint64_t>(a[k]) != std::bit_cast<std::uint64_t>(b[k])) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return topograsp::fuzz::run_input(data, size, [&] {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::string input = "text = " + c_literal(text);
    const std::string prefix = std::string(k_file) + ": ";
    KeypointGrasp g;
    try {
      g = topograsp::parse_keypoint_grasp(text, std::string(k_file));
    } catch (const topograsp::keypoint_error& e) {
      // The documented error: it must name the file first.
      if (std::string_view(e.what()).substr(0, prefix.size()) != prefix)
        fuzz_fail("keypoint_grasp",
                  "the keypoint_error does not name the file: " + c_literal(e.what()), input);
      return;
    } catch (const std::exception& e) {
      fuzz_fail("keypoint_grasp",
                std::string("parse_keypoint_grasp threw ") + typeid(e).name() +
                    " (not topograsp::keypoint_error): " + e.what(),
                input);
    }
    if (g.object.empty()) fuzz_fail("keypoint_grasp", "parsed an empty object name", input);
    bool small = true;  // every coordinate below 1e6 in magnitude
    for (std::size_t i = 0; i < g.keypoints.size(); ++i) {
      if (!g.keypoints[i].allFinite())
        fuzz_fail("keypoint_grasp",
                  "keypoint " + std::to_string(i) + " is not finite: " + vec_str(g.keypoints[i]),
                  input);
      small = small && g.keypoints[i].cwiseAbs().maxCoeff() < 1e6;
    }

    const std::string written = topograsp::keypoint_grasp_json(g);
    KeypointGrasp again;
    try {
      again = topograsp::parse_keypoint_grasp(written, std::string(k_file));
    } catch (const std::exception& e) {
      fuzz_fail("keypoint_grasp", std::string("the written grasp does not parse: ") + e.what(),
                input + "\nwritten = " + c_literal(written));
    }
    if (again.object != g.object)
      fuzz_fail("keypoint_grasp",
                "writing and parsing changed the object name " + c_literal(g.object) + " to " +
                    c_literal(again.object),
                input + "\nwritten = " + c_literal(written));
    for (std::size_t i = 0; i < g.keypoints.size(); ++i)
      if (!same_bits(g.keypoints[i], again.keypoints[i]))
        fuzz_fail("keypoint_grasp",
                  "writing and parsing changed keypoint " + std::to_string(i) + " from " +
                      vec_str(g.keypoints[i]) + " to " + vec_str(again.keypoints[i]),
                  input + "\nwritten = " + c_literal(written));

    Eigen::Vector4d w;
    try {
      w = topograsp::keypoint_windings(g, Vec3::Zero());
    } catch (const topograsp::invalid_argument& e) {
      if (small)
        fuzz_fail("keypoint_grasp",
                  std::string("keypoint_windings threw for keypoints below 1e6: ") + e.what(),
                  input);
      return;  // documented for keypoints so far apart that a difference overflows
    } catch (const std::exception& e) {
      fuzz_fail("keypoint_grasp",
                std::string("keypoint_windings threw ") + typeid(e).name() +
                    " (not topograsp::invalid_argument): " + e.what(),
                input);
    }
    for (int f = 0; f < 4; ++f)
      if (!(std::isfinite(w[f]) && w[f] >= 0.0 && w[f] <= 4.0 * (1.0 + 1e-12)))
        fuzz_fail("keypoint_grasp",
                  "the winding of curve " + std::to_string(f) + " is " + num(w[f]) +
                      ", not finite in [0, 4]",
                  input);
  });
}
