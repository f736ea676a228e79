// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: import_hand (io/hand_import.hpp) on any bytes read as XML.
//
// - Only topograsp::xml_error (the text is not XML) and topograsp::import_error (it is no hand
//   the model can hold) may escape; both name the file first.
// - What imports, make_model() accepts: the checks below mirror make_model()'s, made here on their
//   own (links first the root, parents earlier, names unique over links and frames and at most 31
//   characters, finite limits in order, non-zero axes, couplings to actuated joints, shapes and
//   frames on known links with positive sizes, finite numbers within the model's ranges).
// - A URDF hand holds every <link> of the file (no link is dropped for want of a joint from the
//   root: a cycle beside the tree is refused).
// - model_header() writes the hand, naming every link, with no control character but the line
//   ends (nothing from the file can break a comment or a string literal).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include <topograsp/io/hand_import.hpp>

#include "fuzz_input.hpp"

namespace {

using topograsp::fuzz::c_literal;
using topograsp::fuzz::fuzz_fail;

constexpr std::string_view k_file = "fuzz.xml";

bool finite(std::initializer_list<double> v, double bound) {
  return std::all_of(v.begin(), v.end(),
                     [bound](double x) { return std::isfinite(x) && std::abs(x) < bound; });
}

// Why make_model() would refuse \p h, or empty.
std::string refusal(const topograsp::ImportedHand& h) {
  using namespace topograsp;
  if (h.links.empty()) return "no link";
  if (h.joint_names.size() != h.links.size()) return "joint_names and links differ in size";
  std::vector<std::string_view> names;
  const auto known = [&](const Name& n, std::size_t upto) {
    return std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(upto), n.view()) !=
           names.begin() + static_cast<std::ptrdiff_t>(upto);
  };
  for (std::size_t i = 0; i < h.links.size(); ++i) {
    const LinkSpec& l = h.links[i];
    const std::string at = "link " + std::to_string(i) + " " + c_literal(l.name.view());
    if (l.name.empty() || l.name.size() > max_name_length) return at + ": bad name";
    if (known(l.name, names.size())) return at + ": a repeated name";
    if ((i == 0) != l.parent.empty()) return at + ": the root is not first";
    if (i > 0 && !known(l.parent, names.size())) return at + ": its parent is not earlier";
    names.push_back(l.name.view());
    if (!finite({l.origin.p[0], l.origin.p[1], l.origin.p[2], l.com[0], l.com[1], l.com[2], l.mass},
                1e6) ||
        l.mass < 0.0)
      return at + ": origin, mass or centre not finite";
    if (!finite({l.origin.R[0], l.origin.R[4], l.origin.R[8]}, 2.0))
      return at + ": a rotation that is not one";
    if (l.type == JointType::fixed) {
      if (l.effort != 0.0 || !l.mimic.empty()) return at + ": a fixed joint with an actuator";
      continue;
    }
    if (!(std::abs(l.axis[0]) + std::abs(l.axis[1]) + std::abs(l.axis[2]) >= 1e-12))
      return at + ": zero axis";
    if (!finite({l.lower, l.upper}, 1e300) || l.lower > l.upper) return at + ": bad limits";
    if (!(l.effort >= 0.0 && l.effort < 1e9 && l.velocity >= 0.0 && l.velocity < 1e9 &&
          l.armature >= 0.0 && l.armature < 1e9))
      return at + ": actuator out of range";
    if (!l.mimic.empty()) {
      if (l.effort != 0.0 || l.armature != 0.0) return at + ": a coupled joint with an actuator";
      const auto s = std::find_if(h.links.begin(), h.links.end(),
                                  [&](const LinkSpec& x) { return x.name == l.mimic; });
      if (s == h.links.end() || s->type == JointType::fixed || !s->mimic.empty())
        return at + ": coupled to a joint that is not actuated";
    }
  }
  const std::size_t n_links = names.size();
  for (const ShapeSpec& s : h.shapes) {
    if (!known(s.link, n_links)) return "a shape on an unknown link " + c_literal(s.link.view());
    const auto& z = s.size;
    const bool ok = s.type == ShapeType::box      ? (z[0] > 0.0 && z[1] > 0.0 && z[2] > 0.0)
                    : s.type == ShapeType::sphere ? z[0] > 0.0
                                                  : (z[0] > 0.0 && z[1] >= 0.0);
    if (!ok || !finite({z[0], z[1], z[2], s.pose.p[0], s.pose.p[1], s.pose.p[2]}, 1e6))
      return "a shape of " + c_literal(s.link.view()) + " with a bad size or pose";
  }
  for (const FrameSpec& f : h.frames) {
    if (!known(f.link, n_links)) return "a frame on an unknown link " + c_literal(f.link.view());
    if (f.name.empty() || known(f.name, names.size()))
      return "frame " + c_literal(f.name.view()) + ": empty or repeated name";
    names.push_back(f.name.view());
  }
  return {};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return topograsp::fuzz::run_input(data, size, [&] {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    topograsp::ImportedHand hand;
    try {
      hand = topograsp::import_hand(topograsp::parse_xml(text, k_file));
    } catch (const topograsp::invalid_argument& e) {  // xml_error and import_error
      if (std::string_view(e.what()).substr(0, k_file.size() + 1) != std::string(k_file) + ":")
        fuzz_fail("hand_import", "the error does not name the file: " + c_literal(e.what()),
                  "text = " + c_literal(text));
      return;
    } catch (const std::exception& e) {
      fuzz_fail("hand_import",
                std::string("import_hand threw ") + typeid(e).name() + ": " + e.what(),
                "text = " + c_literal(text));
    }
    if (const std::string bad = refusal(hand); !bad.empty())
      fuzz_fail("hand_import", "imported what make_model() refuses: " + bad,
                "text = " + c_literal(text));
    if (hand.format == topograsp::HandFileFormat::urdf) {
      const topograsp::XmlDocument doc = topograsp::parse_xml(text, k_file);
      const auto n = std::count_if(doc.root.children.begin(), doc.root.children.end(),
                                   [](const topograsp::XmlElement& e) { return e.name == "link"; });
      if (static_cast<std::size_t>(n) != hand.links.size())
        fuzz_fail("hand_import",
                  "imported " + std::to_string(hand.links.size()) + " of the file's " +
                      std::to_string(n) + " links",
                  "text = " + c_literal(text));
    }
    const std::string header = topograsp::model_header(hand, "fuzz");
    for (const char c : header)
      if ((static_cast<unsigned char>(c) < 0x20 && c != '\n') || c == 0x7f)
        fuzz_fail("hand_import", "a control character in the header", "text = " + c_literal(text));
    for (const topograsp::LinkSpec& l : hand.links)
      if (header.find("\"" + std::string(l.name.view()) + "\"") == std::string::npos)
        fuzz_fail("hand_import", "the header does not name link " + c_literal(l.name.view()),
                  "text = " + c_literal(text));
  });
}
