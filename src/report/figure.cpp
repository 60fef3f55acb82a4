#include "pneumachaos/report/figure.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/atomic_file.hpp"

namespace pneumachaos {
namespace {

void write_text(const std::string& path, const std::string& text) {
  AtomicFile f(path);
  f.stream() << text;
  f.commit();
}

}  // namespace

FigureFiles render_figure(const FigureSpec& spec, const std::string& relative_dir) {
  std::filesystem::create_directories(relative_dir);
  // gnuplot runs inside the directory, so every path given to the shell must be absolute.
  const std::string dir = std::filesystem::absolute(relative_dir).string();
  FigureFiles files{spec.name,
                    spec.caption,
                    spec.name + ".png",
                    spec.name + ".svg",
                    spec.name + ".gp",
                    spec.name + "_plot.gp",
                    {}};
  for (const auto& [file, content] : spec.data) {
    write_text(dir + "/" + file, content);
    files.data.push_back(file);
  }
  write_text(dir + "/" + files.plot_script, "# Plot commands; restyle freely. Rendered by " +
                                                files.script + ".\n" + spec.plot + "\n");
  write_text(dir + "/" + files.script,
             fmt::format("# Renders {0}_plot.gp to PNG and SVG: gnuplot {0}.gp\n"
                         "set terminal pngcairo size {1},{2} enhanced font 'Sans,10'\n"
                         "set output '{0}.png'\n"
                         "load '{0}_plot.gp'\n"
                         "unset multiplot\n"
                         "set output\n"
                         "set terminal svg size {1},{2} dynamic enhanced font 'Sans,10'\n"
                         "set output '{0}.svg'\n"
                         "load '{0}_plot.gp'\n"
                         "unset multiplot\n"
                         "set output\n",
                         spec.name, spec.width, spec.height));
  const std::string log = dir + "/" + spec.name + ".log";
  const std::string command =
      fmt::format("cd '{}' && gnuplot '{}' > '{}' 2>&1", dir, files.script, log);
  const int status = std::system(command.c_str());
  const auto size = [&](const std::string& f) {
    std::error_code ec;
    const auto s = std::filesystem::file_size(dir + "/" + f, ec);
    return ec ? 0 : s;
  };
  if (status != 0 || size(files.png) == 0 || size(files.svg) == 0) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    throw Error(dir + "/" + files.script,
                fmt::format("gnuplot did not render the figure (is gnuplot installed? "
                            "scripts/setup.sh installs it): {}",
                            text.str().substr(0, 600)));
  }
  std::filesystem::remove(log);
  return files;
}

}  // namespace pneumachaos
