#include <fmt/format.h>

#include "pneumachaos/report/reproduce.hpp"

namespace pneumachaos {
namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::string report_html(const std::vector<FigureFiles>& figures, const std::vector<Claim>& claims,
                        const std::string& scenario_toml, const std::string& settings) {
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
      "<title>pneumachaos: Kosaki &amp; Sano reproduced</title>\n<style>\n"
      "body{font-family:sans-serif;max-width:1250px;margin:2em auto;padding:0 1em;color:#222}\n"
      "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:.35em .6em;"
      "vertical-align:top}\n.agrees{background:#e3f4e3}.disagrees{background:#fbe3e3}"
      ".not{background:#f1f1f1}\nfigure{margin:1.5em 0}img{max-width:100%;border:1px solid #ddd}\n"
      "pre{background:#f6f6f6;padding:1em;overflow:auto;font-size:85%}\n</style></head><body>\n"
      "<h1>An analytical and experimental study of chaotic oscillation in a pneumatic cylinder "
      "&mdash; reproduced</h1>\n"
      "<p>Kosaki &amp; San&#333;'s figures and claims, computed by pneumachaos from its built-in "
      "virtual rig. " +
      escape(settings) +
      "</p>\n<h2>The paper's claims against our numbers</h2>\n"
      "<table><tr><th>claim</th><th>paper</th><th>ours</th><th>verdict</th><th>rule</th><th>figure</th></tr>\n";
  for (const Claim& c : claims) {
    const std::string cls =
        c.verdict == "agrees" ? "agrees" : (c.verdict == "disagrees" ? "disagrees" : "not");
    h += fmt::format(
        "<tr class=\"{}\"><td>{}</td><td>{}</td><td>{}</td><td><b>{}</b></td><td>{}</td><td>{}</td>"
        "</tr>\n",
        cls, escape(c.claim), escape(c.paper), escape(c.ours), escape(c.verdict), escape(c.rule),
        c.figure.empty() ? std::string("&ndash;")
                         : fmt::format("<a href=\"#{0}\">{0}</a>", escape(c.figure)));
  }
  h += "</table>\n<h2>Figures</h2>\n<p>Each figure's data, its gnuplot commands "
       "(<code>NAME_plot.gp</code>) and the driver that renders PNG and SVG "
       "(<code>gnuplot NAME.gp</code>) are in <code>figures/</code>.</p>\n";
  for (const FigureFiles& f : figures) {
    h += fmt::format(
        "<figure id=\"{0}\"><img src=\"figures/{1}\" alt=\"{2}\">\n<figcaption>{2} "
        "<a href=\"figures/{3}\">SVG</a> &middot; <a href=\"figures/{4}\">script</a>",
        escape(f.name), escape(f.png), escape(f.caption), escape(f.svg), escape(f.plot_script));
    for (const auto& d : f.data)
      h += fmt::format(" &middot; <a href=\"figures/{0}\">{0}</a>", escape(d));
    h += "</figcaption></figure>\n";
  }
  h += "<h2>The scenario</h2>\n<pre>" + escape(scenario_toml) + "</pre>\n</body></html>\n";
  return h;
}

}  // namespace pneumachaos
