#include "pneumachaos/plot/figure.hpp"

#include <fmt/format.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"
#include "pneumachaos/io/atomic_file.hpp"

namespace pneumachaos {
namespace {

void write_text(const std::string& path, const std::string& text) {
  AtomicFile f(path);
  f.stream() << text;
  f.commit();
}

// Runs `gnuplot script` inside dir with its output in log, from an argument vector: no shell
// sees the user's --out path, so quotes or spaces in it can neither break nor inject a command.
// Returns the exit status (or -1 when gnuplot could not be started).
int run_gnuplot(const std::string& dir, const std::string& script, const std::string& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::string program = "gnuplot", argument = script;
  char* argv[] = {program.data(), argument.data(), nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

void FigureSpec::validate() const {
  using namespace validation;
  // The stem names files gnuplot writes and reads inside quoted strings.
  if (name.empty() || name.front() == '.' || name.find_first_of("/\\'\"\n") != std::string::npos)
    throw Error(field("figure.name"), " = " + name, "must be a plain file stem");
  require_between(field("figure.width"), width, 16, 10000, "pixels");
  require_between(field("figure.height"), height, 16, 10000, "pixels");
}

FigureFiles render_figure(const FigureSpec& spec, const std::string& relative_dir) {
  spec.validate();
  std::filesystem::create_directories(relative_dir);
  // gnuplot runs inside the directory: every path handed to it is absolute.
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
  const int status = run_gnuplot(dir, files.script, log);
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
