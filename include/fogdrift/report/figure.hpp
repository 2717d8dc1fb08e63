// A figure as data: panels of named (x, y) series. The same Figure is written as JSON for
// machines and rendered to PNG by gnuplot for people, so the picture and the numbers cannot
// disagree.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace fogdrift::report {

struct Series {
  std::string name;
  std::vector<double> x, y;
  bool points = false;   ///< draw markers (and lines) instead of a plain line
  bool dashed = false;   ///< a reference line
  bool scatter = false;  ///< markers alone, no line between them (a cloud of rows)
};

struct Panel {
  std::string title;
  std::string x_label, y_label;
  std::vector<Series> series;
};

struct Figure {
  std::string name;   ///< file stem: NAME.json, NAME.png
  std::string title;  ///< printed above the panels
  std::vector<Panel> panels;
};

/// {"name", "title", "panels": [{"title", "x_label", "y_label", "series": [{"name", "x": [...],
/// "y": [...]}]}]}; non-finite values are written as null.
std::string to_json(const Figure& figure);

/// A self-contained gnuplot script (data inline) that draws `figure` into `png_name` with the
/// pngcairo terminal, panels stacked vertically.
std::string to_gnuplot(const Figure& figure, const std::string& png_name);

/// The gnuplot program to use: $FOGDRIFT_GNUPLOT if set, else "gnuplot" when it is on PATH;
/// empty when there is none.
std::string find_gnuplot();

/// Writes the figure's script as DIR/NAME.gp and runs `gnuplot` on it in `dir`, drawing
/// DIR/NAME.png. Returns an empty string on success, else what went wrong (no gnuplot, its exit
/// status and messages, or a missing PNG).
std::string render_png(const Figure& figure, const std::filesystem::path& dir,
                       const std::string& gnuplot);

/// Each figure as NAME.json and, drawn by gnuplot, NAME.png into the folder being filled (a
/// fill_directory_atomically folder). Returns what kept a PNG from being drawn, one line each
/// (render_png's); the JSON is written regardless.
std::vector<std::string> write_figures(const std::vector<Figure>& figures,
                                       const std::filesystem::path& folder);

}  // namespace fogdrift::report
