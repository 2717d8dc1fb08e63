#include "fogdrift/report/figure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "test_util.hpp"

namespace fogdrift::report {
namespace {

Figure two_panels() {
  Figure f{"f", "A \"quoted\" title", {}};
  f.panels.push_back({"p1", "x (s)", "y (°/h)", {{"a_b", {0, 1, 2}, {1, 4, 9}}}});
  f.panels.push_back({"p2",
                      "x",
                      "y",
                      {{"with gap", {0, 1, 2}, {1, std::nan(""), 3}, true},
                       {"ref", {0, 2}, {2, 2}, false, true}}});
  return f;
}

TEST(Figure, JsonHoldsEverySeriesAndWritesGapsAsNull) {
  const auto j = nlohmann::json::parse(to_json(two_panels()));
  EXPECT_EQ(j["name"], "f");
  EXPECT_EQ(j["title"], "A \"quoted\" title");
  ASSERT_EQ(j["panels"].size(), 2u);
  EXPECT_EQ(j["panels"][0]["series"][0]["name"], "a_b");
  EXPECT_EQ(j["panels"][0]["series"][0]["y"][2], 9.0);
  EXPECT_TRUE(j["panels"][1]["series"][0]["y"][1].is_null());
  EXPECT_EQ(j["panels"][1]["y_label"], "y");
}

TEST(Figure, GnuplotScriptCarriesTheDataAndEscapesQuotes) {
  const std::string g = to_gnuplot(two_panels(), "f \"1\".png");
  EXPECT_NE(g.find("set output \"f \\\"1\\\".png\""), std::string::npos);
  EXPECT_NE(g.find("A \\\"quoted\\\" title"), std::string::npos);
  EXPECT_NE(g.find("$d0_0 << EOD\n0 1\n1 4\n2 9\nEOD"), std::string::npos);
  EXPECT_NE(g.find("NaN NaN"), std::string::npos);  // a gap is a NaN row
  EXPECT_NE(g.find("set multiplot layout 2,1"), std::string::npos);
  EXPECT_NE(g.find("linespoints"), std::string::npos);
  EXPECT_NE(g.find("dt 2"), std::string::npos);
}

TEST(Figure, RendersAPngWithGnuplotOrSaysWhyNot) {
  test::TempDir dir;
  const std::string gnuplot = find_gnuplot();
  const auto png = dir / "f.png";
  const std::string problem = render_png(two_panels(), dir.path(), gnuplot);
  if (gnuplot.empty()) {
    EXPECT_NE(problem.find("no gnuplot"), std::string::npos);
    GTEST_SKIP() << "gnuplot is not installed (scripts/setup.sh installs gnuplot-nox)";
  }
  ASSERT_EQ(problem, "");
  std::ifstream in(png, std::ios::binary);
  char magic[8] = {};
  in.read(magic, 8);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  EXPECT_TRUE(std::filesystem::exists(dir / "f.gp"));  // kept for the user to restyle
  EXPECT_FALSE(std::filesystem::exists(dir / "f.gp.log"));
  // A failing gnuplot is reported with its exit status and messages, not silently.
  test::TempDir other;
  const std::string bad = render_png(two_panels(), other.path(), "/bin/false");
  EXPECT_NE(bad.find("failed"), std::string::npos);
  const std::string missing = render_png(two_panels(), other.path(), "/nonexistent/gnuplot");
  EXPECT_NE(missing.find("failed"), std::string::npos);
}

}  // namespace
}  // namespace fogdrift::report
