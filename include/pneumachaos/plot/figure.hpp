#pragma once
// A figure as a user can restyle it: its data files, a gnuplot script with the plot commands
// (NAME_plot.gp), a driver (NAME.gp) that renders them to PNG (pngcairo) and SVG, and both
// images. gnuplot is run once per figure in the figure's directory.

#include <string>
#include <utility>
#include <vector>

namespace pneumachaos {

struct FigureSpec {
  std::string name;                                       ///< file stem, e.g. "fig7_record"
  std::string caption;                                    ///< one sentence for the report
  std::vector<std::pair<std::string, std::string>> data;  ///< file name -> content
  std::string plot;               ///< gnuplot commands drawing the figure (no terminal/output)
  int width = 900, height = 520;  ///< pixels (PNG and SVG)
  /// Throws Error naming figure.name (empty, or not a plain file stem: a path separator, a
  /// quote or a leading dot) or figure.width / figure.height (16 to 10000 pixels).
  void validate() const;
};

struct FigureFiles {
  std::string name, caption, png, svg, script, plot_script;
  std::vector<std::string> data;
};

/// Writes the figure's files into dir and runs gnuplot; throws Error with gnuplot's message
/// when gnuplot is missing or fails, or an image comes out empty.
FigureFiles render_figure(const FigureSpec& spec, const std::string& dir);

}  // namespace pneumachaos
