// `slide report` (tools/report.cpp): one self-contained page for a run or a sweep folder; the base64 that embeds its
// images; the sweep's recommendation (tools/sweep/recommendation.hpp).
#include <gtest/gtest.h>

#include <fmt/format.h>


#include "tests/cli_helpers.hpp"
#include "tools/base64.hpp"
#include "tools/sweep/recommendation.hpp"

namespace slide::testing {
namespace {

namespace fs = std::filesystem;

// RFC 4648, section 10.
TEST(Base64, TheRfcTestVectors) {
  EXPECT_EQ(tools::base64(""), "");
  EXPECT_EQ(tools::base64("f"), "Zg==");
  EXPECT_EQ(tools::base64("fo"), "Zm8=");
  EXPECT_EQ(tools::base64("foo"), "Zm9v");
  EXPECT_EQ(tools::base64("foob"), "Zm9vYg==");
  EXPECT_EQ(tools::base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(tools::base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(tools::base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

tools::RunResult result(const std::string& name, tools::RunOutcome o, double error, double setup, double wall) {
  tools::RunResult r;
  r.name = name;
  r.outcome = o;
  r.error = error;
  r.setup_seconds = setup;
  r.wall_seconds = wall;
  return r;
}

TEST(Recommendation, TheCheapestFinishedRunWithinTheTarget) {
  using O = tools::RunOutcome;
  const std::vector<tools::RunResult> runs{
      result("a", O::completed, 0.05, 1.0, 9.0),   // 10 s
      result("b", O::inaccurate, 0.12, 0.5, 1.5),  // 2 s, error too large for 0.1
      result("c", O::completed, 0.09, 1.0, 4.0),   // 5 s: the answer for 0.1
      result("d", O::unstable, tools::RunResult::nan, 0.1, 0.1),
      result("e", O::completed, 0.02, 2.0, 28.0)};
  ASSERT_TRUE(tools::cheapest_within(runs, 0.1));
  EXPECT_EQ(tools::cheapest_within(runs, 0.1)->name, "c");
  EXPECT_EQ(tools::cheapest_within(runs, 0.2)->name, "b");
  EXPECT_EQ(tools::cheapest_within(runs, 0.03)->name, "e");
  EXPECT_FALSE(tools::cheapest_within(runs, 0.01));
}

// base64 back to bytes (the test's own decoder).
std::string from_base64(const std::string& text) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned bits = 0;
  int count = 0;
  for (const char c : text) {
    if (c == '=') break;
    const auto v = alphabet.find(c);
    if (v == std::string::npos) throw std::invalid_argument("not base64");
    bits = (bits << 6) | unsigned(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out += char((bits >> count) & 0xff);
    }
  }
  return out;
}

// Every image of the page is an embedded PNG (data: URL that decodes to a PNG signature); the page names nothing
// outside itself (no src or href but data: URLs) and holds no script. Returns the number of images.
int expect_self_contained(const std::string& html) {
  EXPECT_EQ(html.find("<script"), std::string::npos);
  int images = 0;
  // Every src="..." and href="..." (libstdc++'s std::regex overflows the stack on megabyte attributes: a plain scan).
  for (const std::string attribute : {"src=\"", "href=\""}) {
    for (auto at = html.find(attribute); at != std::string::npos; at = html.find(attribute, at + 1)) {
      const auto begin = at + attribute.size(), end = html.find('"', begin);
      const std::string url = html.substr(begin, end - begin);
      EXPECT_EQ(url.rfind("data:image/png;base64,", 0), 0u) << url.substr(0, 80);
      const std::string png = from_base64(url.substr(std::string("data:image/png;base64,").size()));
      EXPECT_EQ(png.substr(0, 8), "\x89PNG\r\n\x1a\n");
      ++images;
    }
  }
  return images;
}

TEST(Report, ARunsPageIsSelfContainedWithItsFigures) {
  const fs::path dir = fresh_directory("report_run");
  const CommandResult run = run_command(slide_binary() + " run " + (source_dir() / "cases/dam_break_2d.yaml").string() +
                                        " --quiet --out " + (dir / "run").string() +
                                        " --set particle_spacing=0.011430 --set end_time=0.05");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const CommandResult r = run_command(slide_binary() + " report " + (dir / "run").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string html = read_file(dir / "run/report.html");
  EXPECT_NE(html.find("Martin &amp; Moyce dam break"), std::string::npos);
  EXPECT_NE(html.find("Time-step limits"), std::string::npos);
  EXPECT_NE(html.find("method.gradient"), std::string::npos);
  // A sentence, not a JSON object (issue 30).
  EXPECT_NE(html.find("particles: "), std::string::npos);
  EXPECT_NE(html.find(" fluid, "), std::string::npos);
  EXPECT_EQ(html.find("{&quot;"), std::string::npos);
  EXPECT_EQ(html.find("{\"dummy"), std::string::npos);
  // tools/plot_run.py draws the particles, the gauges and the surge front (CI installs Debian's python3-matplotlib
  // and python3-h5py).
  EXPECT_EQ(expect_self_contained(html), 3) << r.output;
  EXPECT_NE(html.find("coloured by phase and by speed"), std::string::npos);
}

TEST(Report, ASweepsPageRecommendsAndListsEveryRun) {
  const fs::path dir = fresh_directory("report_sweep");
  write_file(dir / "s.yaml",
             fmt::format(R"(scene: {}
set: {{end_time: 0.17, output.snapshots: false}}
vary: {{particle_spacing: [0.011430, 0.005715]}}
error: {{measure: dam_break_front, reference: {}, threshold: 0.2}}
)",
                         (source_dir() / "cases/dam_break_2d.yaml").string(),
                         (source_dir() / "cases/reference/martin_moyce_1952_surge_front.csv").string()));
  ASSERT_EQ(run_command(slide_binary() + " sweep " + (dir / "s.yaml").string() + " --out " + (dir / "out").string())
                .exit_code,
            0);
  const CommandResult r = run_command(slide_binary() + " report " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string html = read_file(dir / "out/report.html");
  EXPECT_NE(html.find("The cheapest run within the threshold: <b>run_001</b>"), std::string::npos);
  EXPECT_NE(html.find("<td>run_002</td>"), std::string::npos);
  EXPECT_EQ(expect_self_contained(html), 2);
}

// The page in a real browser (Debian's chromium, headless; tools/test installs it, and the test is skipped with a
// message where it is not there): a copy of the page with a script appended (the page itself has none) writes, once
// loaded, how many images there are, how many did not decode, and every resource fetched that is not a data: URL.
// A control page with one damaged image and one remote image must be caught.
std::string browser_check(const fs::path& page, const fs::path& work) {
  const fs::path copy = work / (page.stem().string() + "_checked.html");
  write_file(copy, read_file(page) + R"(<script>
window.addEventListener('load', () => {
  const images = [...document.images];
  const bad = images.filter(i => !(i.complete && i.naturalWidth > 0)).length;
  const fetched = performance.getEntriesByType('resource').map(e => e.name).filter(n => !n.startsWith('data:'));
  const p = document.createElement('p');
  p.id = 'browser-check';
  p.textContent = `images=${images.length} undecoded=${bad} fetched=${fetched.length}`;
  document.body.appendChild(p);
});
</script>
)");
  const CommandResult r = run_command("timeout 120 chromium --headless --no-sandbox --disable-gpu "
                                      "--disable-dev-shm-usage --dump-dom 'file://" +
                                      copy.string() + "' 2>/dev/null");
  const auto at = r.output.find("id=\"browser-check\">");
  if (at == std::string::npos) return "no result: " + r.output.substr(0, 200);
  const auto begin = r.output.find('>', at) + 1;
  return r.output.substr(begin, r.output.find('<', begin) - begin);
}

TEST(Report, OpensInAHeadlessBrowserWithEveryImageDecodedAndNothingFetched) {
  if (run_command("command -v chromium").exit_code != 0)
    GTEST_SKIP() << "chromium is not installed (tools/test installs Debian's chromium where it can); the page's "
                    "structure is checked by the other Report tests";
  const fs::path dir = fresh_directory("report_browser");
  const CommandResult run = run_command(slide_binary() + " run " + (source_dir() / "cases/dam_break_2d.yaml").string() +
                                        " --quiet --out " + (dir / "run").string() +
                                        " --set particle_spacing=0.011430 --set end_time=0.05");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  ASSERT_EQ(run_command(slide_binary() + " report " + (dir / "run").string()).exit_code, 0);
  const std::string result = browser_check(dir / "run/report.html", dir);
  // A browser that does not start (no display libraries, no shared memory in a container) says nothing of the page.
  if (result.rfind("no result", 0) == 0) GTEST_SKIP() << "chromium did not load the page here: " << result;
  EXPECT_EQ(result, "images=3 undecoded=0 fetched=0");
  // The control: one image damaged, one remote.
  std::string page = read_file(dir / "run/report.html");
  const auto data = page.find("base64,") + 7;
  page.replace(data, 40, "AAAA");
  page.replace(page.find("</body>"), 0, "<img src=\"http://example.invalid/x.png\">");
  write_file(dir / "control.html", page);
  EXPECT_EQ(browser_check(dir / "control.html", dir), "images=4 undecoded=2 fetched=1");
}

TEST(Report, AFolderThatIsNeitherExitsTwo) {
  const fs::path dir = fresh_directory("report_none");
  EXPECT_EQ(run_command(slide_binary() + " report " + dir.string()).exit_code, 2);
  EXPECT_FALSE(fs::exists(dir / "report.html"));
}

}  // namespace
}  // namespace slide::testing
