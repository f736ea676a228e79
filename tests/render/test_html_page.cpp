// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <topograsp/render/html_page.hpp>
#include <topograsp/render/svg_panels.hpp>
#include <topograsp/render/svg_plot.hpp>
#include <topograsp/render/svg_scene.hpp>
#include <vector>

#include "support/text.hpp"

using namespace topograsp;

namespace {

using test::count;

HtmlPage sample_page() {
  HtmlPage page;
  page.title = "Results <hammer & bottle>";
  page.intro = "Two grasps.";
  page.header = {"grasp", "method", "verdict", "time (ms)"};
  page.rows = {{"hammer 3", "topological", "stable", "12.5"},
               {"bottle 1", "<script>alert(1)</script>", "unstable", "-3e-2"}};
  page.figures = {{"hammer_3.svg", "hammer, grasp 3"}, {"plots/fig 7.svg", "windings"}};
  return page;
}

// A temporary directory removed at the end of the scope.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    std::string templ = (std::filesystem::temp_directory_path() / "topograsp-html-XXXXXX").string();
    REQUIRE(mkdtemp(templ.data()) != nullptr);
    path = templ;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
};

std::string read_file(const std::filesystem::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("the results page has the table and the figures, escaped", "[render][html_page]") {
  const std::string html = html_page(sample_page());
  CHECK(html.rfind("<!DOCTYPE html>", 0) == 0);
  CHECK(html.substr(html.size() - 8) == "</html>\n");
  CHECK(count(html, "<style>") == 1);
  CHECK(count(html, "<script") == 0);  // the cell's text is escaped
  CHECK(count(html, "&lt;script&gt;alert(1)&lt;/script&gt;") == 1);
  CHECK(count(html, "<title>Results &lt;hammer &amp; bottle&gt;</title>") == 1);
  CHECK(count(html, "<table>") == 1);
  CHECK(count(html, "<th>") == 4);
  CHECK(count(html, "<tr>") == 3);
  CHECK(count(html, "<td") == 8);
  CHECK(count(html, "<td class=\"num\">12.5</td>") == 1);
  CHECK(count(html, "<td class=\"num\">-3e-2</td>") == 1);
  CHECK(count(html, "<td class=\"stable\">stable</td>") == 1);
  CHECK(count(html, "<td class=\"unstable\">unstable</td>") == 1);
  CHECK(count(html, "<img ") == 2);
  CHECK(count(html, "<img src=\"hammer_3.svg\"") == 1);
  CHECK(count(html, "<img src=\"plots/fig%207.svg\"") == 1);
  CHECK(count(html, "<figcaption>hammer, grasp 3</figcaption>") == 1);
  CHECK(html.find("hammer_3.svg") < html.find("fig%207.svg"));
  CHECK(html == html_page(sample_page()));

  HtmlPage bare;
  bare.title = "nothing";
  const std::string empty = html_page(bare);
  CHECK(count(empty, "<table") == 0);
  CHECK(count(empty, "<img") == 0);
  CHECK(count(empty, "<h1>nothing</h1>") == 1);
}

TEST_CASE("bad page input throws naming the argument", "[render][html_page]") {
  const auto message = [](const HtmlPage& p) -> std::string {
    try {
      (void)html_page(p);
    } catch (const topograsp::invalid_argument& e) {
      return e.what();
    }
    return "no exception";
  };
  HtmlPage p = sample_page();
  p.rows[1].pop_back();
  CHECK(message(p).rfind("rows:", 0) == 0);
  for (const char* bad : {"", "/tmp/a.svg", "file:///tmp/a.svg", "C:\\a.svg"}) {
    p = sample_page();
    p.figures[0].image = bad;
    CHECK(message(p).rfind("figures:", 0) == 0);
  }
  CHECK_THROWS_AS(write_html_page("/nonexistent-dir/index.html", sample_page()),
                  topograsp::invalid_argument);
}

TEST_CASE("the page loads in headless Chromium with its table and every image",
          "[render][html_page][chromium]") {
  const char* chromium = "/usr/bin/chromium";
  if (!std::filesystem::exists(chromium)) {
    WARN("skipped: " << chromium << " is not installed (Debian package chromium)");
    return;
  }
  const TempDir dir;
  // Three figures: a scene, side-by-side panels, a plot (one in a subfolder with a space).
  SvgScene scene;
  scene.add(Primitive::sphere(Vec3::Zero(), 0.05), svg_colours::skin, "hand");
  scene.add_polyline({Vec3(0, 0, 0), Vec3(0.1, 0, 0)}, svg_colours::curve(0), "gamma");
  scene.write((dir.path / "scene.svg").string());
  const std::vector<SvgPanel> panels{{scene, SvgCamera{}, "left", {}},
                                     {scene, SvgCamera{}, "right", {}}};
  write_svg((dir.path / "panels.svg").string(), svg_panels(panels, "two"));
  std::filesystem::create_directories(dir.path / "plots");
  SvgLinePlot plot("windings", "t", "w");
  plot.add_series("w", {0, 1, 2}, {0, 0.5, 1});
  plot.write((dir.path / "plots" / "fig 7.svg").string());

  HtmlPage page = sample_page();
  page.figures = {{"scene.svg", "a scene"}, {"panels.svg", "panels"}, {"plots/fig 7.svg", "plot"}};
  write_html_page((dir.path / "index.html").string(), page);

  // The test copy of the page reports, after loading, how many images decoded to a non-zero
  // size and what the table shows.
  const std::string probe = R"(<script>
window.addEventListener('load', function () {
  var imgs = document.querySelectorAll('img'), ok = 0;
  for (var i = 0; i < imgs.length; ++i)
    if (imgs[i].complete && imgs[i].naturalWidth > 0 && imgs[i].getBoundingClientRect().width > 0) ++ok;
  var t = document.querySelector('table');
  var rows = t ? t.querySelectorAll('tbody tr').length : -1;
  var shown = t ? t.getBoundingClientRect().height > 0 : false;
  var r = document.createElement('pre');
  r.id = 'probe';
  r.textContent = 'images=' + imgs.length + ' loaded=' + ok + ' rows=' + rows + ' shown=' + shown;
  document.body.appendChild(r);
});
</script>
</body>)";
  const auto run = [&](const std::string& name, std::string html) {
    const std::size_t at = html.rfind("</body>");
    REQUIRE(at != std::string::npos);
    html.replace(at, 7, probe);
    detail::write_text_file((dir.path / name).string(), html);
    const std::filesystem::path dom = dir.path / (name + ".dom"), err = dir.path / (name + ".err");
    const std::string command =
        std::string(chromium) +
        " --headless --no-sandbox --disable-gpu --disable-background-networking"
        " --disable-component-update --disable-sync --no-first-run --user-data-dir='" +
        (dir.path / "profile").string() + "' --dump-dom 'file://" + (dir.path / name).string() +
        "' > '" + dom.string() + "' 2> '" + err.string() + "'";
    const int status = std::system(command.c_str());
    INFO(read_file(err));
    CHECK(status == 0);
    const std::string out = read_file(dom);
    const std::size_t p = out.find("<pre id=\"probe\">");
    REQUIRE(p != std::string::npos);
    return out.substr(p + 16, out.find("</pre>", p) - p - 16);
  };
  const std::string page_check = run("check.html", html_page(page));
  CHECK(page_check == "images=3 loaded=3 rows=2 shown=true");
  // The probe notices a missing image.
  page.figures.push_back({"missing.svg", "not there"});
  const std::string broken = run("broken.html", html_page(page));
  CHECK(broken == "images=4 loaded=3 rows=2 shown=true");
  // The page itself (no probe) parses to the same table and images.
  const std::filesystem::path dom = dir.path / "index.dom";
  const std::string command =
      std::string(chromium) +
      " --headless --no-sandbox --disable-gpu --disable-background-networking"
      " --disable-component-update --disable-sync --no-first-run --user-data-dir='" +
      (dir.path / "profile").string() + "' --dump-dom 'file://" +
      (dir.path / "index.html").string() + "' > '" + dom.string() + "' 2> /dev/null";
  CHECK(std::system(command.c_str()) == 0);
  const std::string index_dom = read_file(dom);
  CHECK(count(index_dom, "<img ") == 3);
  CHECK(count(index_dom, "<tr>") == 3);
}
