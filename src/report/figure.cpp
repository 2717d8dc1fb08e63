#include "fogdrift/report/figure.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/csv.hpp"

namespace fogdrift::report {
namespace {

nlohmann::ordered_json numbers(const std::vector<double>& v) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (double x : v) {
    if (std::isfinite(x))
      a.push_back(x);
    else
      a.push_back(nullptr);
  }
  return a;
}

// gnuplot strings in double quotes: escape backslashes and quotes.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// A shell word in single quotes.
std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'')
      out += "'\\''";
    else
      out += c;
  }
  return out + "'";
}

}  // namespace

std::string to_json(const Figure& figure) {
  nlohmann::ordered_json j;
  j["name"] = figure.name;
  j["title"] = figure.title;
  j["panels"] = nlohmann::ordered_json::array();
  for (const Panel& p : figure.panels) {
    nlohmann::ordered_json pj;
    pj["title"] = p.title;
    pj["x_label"] = p.x_label;
    pj["y_label"] = p.y_label;
    pj["series"] = nlohmann::ordered_json::array();
    for (const Series& s : p.series) {
      pj["series"].push_back({{"name", s.name}, {"x", numbers(s.x)}, {"y", numbers(s.y)}});
    }
    j["panels"].push_back(std::move(pj));
  }
  return j.dump(1) + "\n";
}

std::string to_gnuplot(const Figure& figure, const std::string& png_name) {
  std::ostringstream g;
  const std::size_t n = figure.panels.size();
  const int height = static_cast<int>(120 + 330 * std::max<std::size_t>(n, 1));
  g << "set terminal pngcairo size 1000," << height << " noenhanced font 'DejaVu Sans,10'\n";
  g << "set output " << quoted(png_name) << "\n";
  g << "set encoding utf8\nset grid lc rgb '#dddddd'\nset key outside right top\n";
  g << "set datafile missing 'NaN'\n";
  // Data blocks first, one per series.
  for (std::size_t p = 0; p < n; ++p) {
    const Panel& panel = figure.panels[p];
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      const Series& series = panel.series[s];
      g << "$d" << p << "_" << s << " << EOD\n";
      for (std::size_t i = 0; i < series.x.size() && i < series.y.size(); ++i) {
        const bool ok = std::isfinite(series.x[i]) && std::isfinite(series.y[i]);
        g << (ok ? csv::format_number(series.x[i]) : "NaN") << ' '
          << (ok ? csv::format_number(series.y[i]) : "NaN") << "\n";
      }
      g << "EOD\n";
    }
  }
  g << "set multiplot layout " << std::max<std::size_t>(n, 1) << ",1 title " << quoted(figure.title)
    << " font ',12'\n";
  for (std::size_t p = 0; p < n; ++p) {
    const Panel& panel = figure.panels[p];
    g << "set title " << quoted(panel.title) << "\n";
    g << "set xlabel " << quoted(panel.x_label) << "\n";
    g << "set ylabel " << quoted(panel.y_label) << "\n";
    if (panel.series.empty()) {
      g << "plot NaN notitle\n";
      continue;
    }
    g << "plot ";
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      const Series& series = panel.series[s];
      if (s) g << ", \\\n     ";
      g << "$d" << p << "_" << s << " using 1:2 with "
        << (series.scatter  ? "points pt 7 ps 0.5"
            : series.points ? "linespoints pt 7 ps 0.8"
                            : "lines")
        << " lw 1.5" << (series.dashed ? " dt 2 lc rgb 'black'" : "") << " title "
        << quoted(series.name);
    }
    g << "\n";
  }
  g << "unset multiplot\nunset output\n";
  return g.str();
}

std::string find_gnuplot() {
  if (const char* env = std::getenv("FOGDRIFT_GNUPLOT"); env && *env) return env;
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(dir) / "gnuplot";
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec)) return candidate.string();
  }
  return {};
}

std::string render_png(const Figure& figure, const std::filesystem::path& dir,
                       const std::string& gnuplot) {
  if (gnuplot.empty()) return "no gnuplot found (install gnuplot-nox or set FOGDRIFT_GNUPLOT)";
  // The script stays beside the PNG, with relative names, so a user can restyle and re-run it.
  const std::string png = figure.name + ".png", script = figure.name + ".gp";
  const std::string log = figure.name + ".gp.log";
  write_text_atomically(dir / script, to_gnuplot(figure, png));
  const std::string command = "cd " + shell_quoted(dir.string()) + " && " + shell_quoted(gnuplot) +
                              " " + shell_quoted(script) + " 2> " + shell_quoted(log) + " >&2";
  const int status = std::system(command.c_str());
  std::string messages;
  {
    std::ifstream in(dir / log);
    std::getline(in, messages, '\0');
  }
  std::error_code ec;
  std::filesystem::remove(dir / log, ec);
  if (status != 0) {
    return fmt::format("{} failed on {} (exit status {}): {}", gnuplot, script, status, messages);
  }
  if (!std::filesystem::is_regular_file(dir / png, ec) ||
      std::filesystem::file_size(dir / png, ec) == 0) {
    return fmt::format("{} wrote no {}", gnuplot, png);
  }
  return {};
}

std::vector<std::string> write_figures(const std::vector<Figure>& figures,
                                       const std::filesystem::path& folder) {
  const std::string gnuplot = find_gnuplot();
  std::vector<std::string> problems;
  for (const Figure& f : figures) {
    write_text_atomically(folder / (f.name + ".json"), to_json(f));
    const std::string problem = render_png(f, folder, gnuplot);
    if (!problem.empty()) problems.push_back(problem);
  }
  return problems;
}

}  // namespace fogdrift::report
