// SPDX-License-Identifier: BSD-3-Clause
// Records human grasps as keypoint files (the format grasp_transfer --demonstrations reads): the
// human hand's planned demonstrations of an object (every box hypothesis, as grasp_transfer runs
// them), the first COUNT stable ones written as their 21 keypoints (human_keypoints), each
// keypoint moved by Gaussian noise of NOISE mm per axis (a hand tracker's error; Box-Muller on
// SplitMix64 from SEED, so the files are the same on every machine). Files are written atomically
// as DIR/<object>_<hypothesis>.json. This is how data/demonstrations/ was made (docs/transfer.md).
//
//   record_demonstrations --object NAME [--out DIR] [--count N] [--noise MM] [--seed S]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <grasp_transfer/command_line.hpp>
#include <topograsp/core/random.hpp>
#include <topograsp/grasp/hypothesis.hpp>
#include <topograsp/grasp/keypoint_fit.hpp>
#include <topograsp/io/keypoint_grasp.hpp>
#include <topograsp/io/text_file.hpp>
#include <topograsp/io/ycb_objects.hpp>

namespace {

using namespace topograsp;

constexpr std::string_view usage =
    "usage: record_demonstrations --object NAME [--out DIR] [--count N] [--noise MM] [--seed S]\n"
    "Plans the human hand's demonstrations of object NAME and writes the first N (default 4)\n"
    "stable ones as keypoint files DIR/<object>_<hypothesis>.json (default DIR: demonstrations),\n"
    "each keypoint moved by Gaussian noise of MM millimetres per axis (default 0) from seed S\n"
    "(default 1).\n";

struct Options {
  std::string object;
  std::filesystem::path out = "demonstrations";
  int count = 4;
  double noise_mm = 0.0;
  std::uint64_t seed = 1;
};

Options parse(std::span<char*> args) {
  Options o;
  std::vector<std::string_view> seen;  // the options given so far
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string_view a = args[i];
    if (a == "--help" || a == "-h") {
      std::fputs(usage.data(), stdout);
      std::exit(0);
    }
    if (a != "--object" && a != "--out" && a != "--count" && a != "--noise" && a != "--seed")
      throw invalid_argument("unknown option " + detail::quote_argument(a) + " (--help)");
    if (std::find(seen.begin(), seen.end(), a) != seen.end())
      detail::throw_invalid_argument(a, "given twice");
    seen.push_back(a);
    if (i + 1 == args.size() || std::string_view(args[i + 1]).empty() ||
        std::string_view(args[i + 1]).starts_with("--"))
      detail::throw_invalid_argument(a, "expected a value");
    const std::string_view v = args[++i];
    if (a == "--object") {
      o.object = v;
    } else if (a == "--out") {
      o.out = std::string(v);
    } else if (a == "--count") {
      o.count = detail::parse_cli_number<int>(v, a);
      if (o.count < 1) detail::throw_invalid_argument(a, "expected at least 1");
    } else if (a == "--noise") {
      o.noise_mm = detail::parse_cli_number<double>(v, a);
      if (!(o.noise_mm >= 0.0 && o.noise_mm <= 50.0))
        detail::throw_invalid_argument(a, "expected 0 to 50 mm");
    } else {
      o.seed = detail::parse_cli_number<std::uint64_t>(v, a);
    }
  }
  if (o.object.empty()) detail::throw_invalid_argument("--object", "expected the object's name");
  return o;
}

// A standard normal number (Box-Muller on two uniform numbers in (0, 1]).
double gaussian(detail::SplitMix64& rng) {
  const double u = 1.0 - rng.uniform(), v = rng.uniform();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * pi * v);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  GraspObject object;
  try {
    o = parse(std::span(argv, static_cast<std::size_t>(argc)));
    std::optional<GraspObject> found = objects::find_any(o.object);
    if (!found)
      detail::throw_invalid_argument("--object",
                                     "unknown object " + detail::quote_argument(o.object));
    object = std::move(*found);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "record_demonstrations: %s\n", e.what());
    return 2;
  }
  try {
    std::filesystem::create_directories(o.out);
    detail::SplitMix64 rng{o.seed};
    const std::vector<GraspHypothesis> hyps = box_hypotheses(object);
    int written = 0;
    for (int id = 0; id < static_cast<int>(hyps.size()) && written < o.count; ++id) {
      const HumanGrasp g = demonstrate(object, hyps[static_cast<std::size_t>(id)], id);
      if (!g.stable()) continue;
      KeypointGrasp k = human_keypoints(source_grasp(g), object.name);
      for (Vec3& p : k.keypoints)
        for (int a = 0; a < 3; ++a) p[a] += 1e-3 * o.noise_mm * gaussian(rng);
      char source[256];
      std::snprintf(source, sizeof source,
                    "topograsp record_demonstrations: the human model's stable planned "
                    "demonstration %d of %s, keypoints with %.3g mm Gaussian noise (seed %llu)",
                    id, object.name.c_str(), o.noise_mm, static_cast<unsigned long long>(o.seed));
      const std::filesystem::path file = o.out / (object.name + "_" + std::to_string(id) + ".json");
      detail::write_text_file(file, keypoint_grasp_json(k, source));
      std::printf("%s\n", file.string().c_str());
      ++written;
    }
    if (written < o.count)
      std::fprintf(stderr, "record_demonstrations: only %d stable demonstrations of %s\n", written,
                   object.name.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "record_demonstrations: %s\n", e.what());
    return 1;
  }
  return 0;
}
