// SPDX-License-Identifier: BSD-3-Clause
// topograsp_import_hand: a URDF or MJCF file to the C++ header of its links, collision shapes and
// frames as constexpr arrays (io/hand_import.hpp), for make_model() and a hand description written
// beside it (docs/models.md, "Bring your own hand"). The CMake function topograsp_import_hand()
// runs it at build time.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <topograsp/io/hand_import.hpp>
#include <topograsp/io/text_file.hpp>

namespace {

constexpr const char* usage =
    "usage: topograsp_import_hand FILE --out HEADER --namespace NS [--root NAME]\n"
    "                             [--mesh-dir DIR] [--skip-missing-meshes] [--comment TEXT]...\n"
    "                             [--description JSON]\n"
    "Reads the URDF or MJCF FILE and writes HEADER: its links (with their joints), collision\n"
    "shapes and frames (MJCF sites) as the constexpr arrays NS::links, NS::shapes and NS::frames\n"
    "for topograsp::make_model(); with --description, also NS::model, the hand it describes.\n"
    "  --root NAME            start at the link (URDF) or body (MJCF) NAME: a hand cut off an arm\n"
    "  --mesh-dir DIR         look mesh files up in DIR (default: beside FILE; MJCF: its meshdir)\n"
    "  --skip-missing-meshes  leave out collision meshes that cannot be read (listed as notes)\n"
    "  --comment TEXT         a line at the top of HEADER (where FILE comes from, its licence)\n"
    "  --description JSON     the hand description file: fingers, thumb, palm centre, closing\n"
    "                         directions, motors, held joints (docs/models.md)\n"
    "Exit status: 0 written, 1 the file cannot be imported, 2 a wrong command line.\n";

int wrong(const std::string& why) {
  std::fprintf(stderr, "topograsp_import_hand: %s\n%s", why.c_str(), usage);
  return 2;
}

// Whether paths a and b name the same file: equivalent() when both exist (another spelling, a
// link), else the same absolute path.
bool same_file(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  return fs::absolute(a, ec).lexically_normal() == fs::absolute(b, ec).lexically_normal();
}

}  // namespace

int main(int argc, char** argv) {
  std::string file, out, ns, description;
  std::vector<std::string> comments;
  topograsp::ImportOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    const auto value = [&](std::string& target) {
      if (i + 1 >= argc) return false;
      target = argv[++i];
      return true;
    };
    if (a == "--help" || a == "-h") {
      std::fputs(usage, stdout);
      return 0;
    }
    bool ok = true;
    if (a == "--out") {
      ok = value(out);
    } else if (a == "--namespace") {
      ok = value(ns);
    } else if (a == "--root") {
      ok = value(options.root);
    } else if (a == "--mesh-dir") {
      ok = value(options.mesh_dir);
    } else if (a == "--description") {
      ok = value(description);
    } else if (a == "--comment") {
      ok = value(comments.emplace_back());
    } else if (a == "--skip-missing-meshes") {
      options.skip_missing_meshes = true;
    } else if (!a.empty() && a[0] == '-') {
      return wrong("unknown option " + std::string(a));
    } else if (file.empty()) {
      file = a;
    } else {
      return wrong("more than one FILE (" + file + ", " + std::string(a) + ")");
    }
    if (!ok) return wrong(std::string(a) + " needs a value");
  }
  if (file.empty()) return wrong("no FILE");
  if (out.empty()) return wrong("no --out HEADER");
  if (ns.empty()) return wrong("no --namespace NS");
  try {  // the namespace is checked before the file is read: model_header's check, on no hand
    (void)topograsp::model_header(topograsp::ImportedHand{}, ns);
  } catch (const topograsp::invalid_argument& e) {
    return wrong(std::string("--namespace: ") + e.what());
  }
  try {  // a line break (or any control character) in a comment would end its line in HEADER
    for (const std::string& c : comments)
      (void)topograsp::detail::header_text(c, topograsp::detail::HeaderText::comment, "--comment");
  } catch (const topograsp::invalid_argument& e) {
    return wrong(e.what());
  }
  if (same_file(file, out))
    return wrong("--out " + out + " is FILE " + file + ": writing it would replace the file");
  std::string header;
  std::size_t links = 0, shapes = 0, frames = 0, notes = 0;
  try {
    topograsp::ImportedHand hand = topograsp::import_hand_file(file, options);
    if (description.empty()) {
      header = topograsp::model_header(hand, ns, comments);
    } else {
      const topograsp::HandDescription d = topograsp::describe_hand_file(hand, description);
      topograsp::detail::check_importable(hand);  // what the description added, too
      header = topograsp::model_header(hand, ns, comments, &d);
    }
    links = hand.links.size();
    shapes = hand.shapes.size();
    frames = hand.frames.size();
    notes = hand.notes.size();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "topograsp_import_hand: %s\n", e.what());
    return 1;
  }
  try {  // a temporary file, then renamed: a failed run never leaves half a header
    topograsp::detail::write_text_file(out, header);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "topograsp_import_hand: --out %s\n", e.what());
    return 1;
  }
  std::printf("%s: %zu links, %zu collision shapes, %zu frames", file.c_str(), links, shapes,
              frames);
  std::printf(notes == 0 ? "\n" : ", %zu notes (in the header)\n", notes);
  return 0;
}
