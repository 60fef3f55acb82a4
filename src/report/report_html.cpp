#include <fmt/format.h>

#include "pneumachaos/report/reproduce.hpp"
#include "pneumachaos/claims/explanations.hpp"

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

// What the reader must know before any number: the rig is not the paper's model (the evidence
// for each difference is docs/notes/virtual_rig.md).
const char* kVirtualRig =
    "<h2>The virtual rig</h2>\n<p>The paper's model (eq. 4 friction, one rigid mass, chamber "
    "volumes following the piston, an ideal supply) gives damped or self-excited oscillation "
    "but no chaos: the paper found chaos only on its test rig. Our maps and Figs. 3 and 7 come "
    "from a <em>virtual rig</em> with the paper's structure (one rigid moving mass m, the "
    "volumes following the piston over a 500 mm stroke) whose parts the paper does not give "
    "are calibrated on its claims within bounds that have a source "
    "(<code>scenarios/calibrations/paper.toml</code>). It differs from the paper's model in "
    "two ways:</p>\n<ul>\n"
    "<li><b>A generalized Maxwell-slip seal</b> (4 elements, 1e6 N/m of presliding "
    "stiffness) on a wide Stribeck curve (Fc 22.8 N, Fs 31.9 N, vs 45 mm/s) that rises with "
    "the chamber pressures (22 and 31 N/MPa) instead of eq. 4: frictional memory and the "
    "negative friction slope of the paper's Fig. 3 across the speeds where the rig runs.</li>\n"
    "<li><b>The air path of a real circuit</b>: a 14.6 cm&sup3; supply line behind a "
    "2.75 mm&sup2; regulator, a 45.5 mm bore with end volumes of 28 and 25 cm&sup3;, and "
    "valves with a critical pressure ratio b = 0.1.</li>\n</ul>\n"
    "<p>It is the default by a written rule (the most claims agreeing on this report, then the "
    "fewest parts without a source): it ties the earlier two-body rig, whose load sat on a "
    "compliant mount without a source (<code>scenarios/variants/compliant_mount.toml</code>). "
    "A run ends at the stroke end or at its duration, whichever comes first. Fig. 2 uses the "
    "paper's own model. The evidence (the variants tried, their exponents and maps, and what "
    "this rig does not reach) is in the repository's <code>docs/notes/virtual_rig.md</code>; "
    "the full scenario is at the end of this page.</p>\n";

// The maps' explorer, filled by report.js from report_data.js (both beside index.html).
const char* kExplore =
    "<h2 id=\"explore-maps\">Explore the maps</h2>\n<p>The four incidence maps of Figs. 4-6 "
    "and the 4.5 kg condition, cell by cell: hover a cell for its runs' verdicts, click it for "
    "its runs (the numbers of the map's <code>runs.csv</code>) and the command that runs each "
    "again alone. The maps are shaded by the regime verdict or, at your choice, by the paper's "
    "three indices. A claim's figure link above leads here and marks the cells its rule read. "
    "The figures below are the same maps for print.</p>\n<div id=\"explore\"><noscript>The "
    "explorer needs JavaScript; the figures and <code>sweeps/*/runs.csv</code> hold the same "
    "data.</noscript></div>\n";

// The row's colour on the page.
std::string verdict_class(const Claim& c) {
  return c.verdict == kAgrees ? "agrees" : c.verdict == kDisagrees ? "disagrees" : "not";
}

std::string claims_table(const std::vector<Claim>& claims) {
  std::string h =
      "<table><tr><th>the paper says</th><th>our reading</th><th>rule</th><th>ours</th>"
      "<th>verdict (margin)</th><th>why</th><th>figure</th></tr>\n";
  for (const Claim& c : claims) {
    const std::string cls = verdict_class(c);
    const std::string margin =
        c.margin == c.margin ? fmt::format(" ({:+.2f})", c.margin) : std::string();
    h += fmt::format(
        "<tr class=\"{}\" id=\"claim-{}\"><td>&ldquo;{}&rdquo; <small>({})</small></td><td>{}</td>"
        "<td>{}</td><td>{}</td><td><b>{}</b>{}</td><td>{}</td><td>{}</td></tr>\n",
        cls, escape(c.id), escape(c.quote), escape(c.where), escape(c.reading), escape(c.rule),
        escape(c.ours), escape(c.verdict), margin, escape(c.why),
        c.figure.empty() ? std::string("&ndash;")
                         : fmt::format("<a href=\"#{0}\">{0}</a>", escape(c.figure)));
  }
  return h + "</table>\n";
}

// The chaos rows again as the paper's judge decides them (the same rules and runs).
std::string paper_judge_table(const std::vector<Claim>& paper) {
  if (paper.empty()) return "";
  std::string h =
      "<h3 id=\"paper-judge\">The chaos claims under the paper's judge</h3>\n<p>The same "
      "rules read the same runs, with the paper's three indices (a spectrum without a dominant "
      "line, an autocorrelation converging to zero, Wolf's exponent positive) deciding which "
      "runs are chaotic instead of the regime verdict. The rows that do not read chaos are the "
      "same under both; every map has a second figure under this judge.</p>\n"
      "<table><tr><th>claim</th><th>ours</th><th>verdict (margin)</th><th>why</th></tr>\n";
  for (const Claim& c : paper) {
    if (!reads_chaos_judge(c.id)) continue;
    const std::string margin =
        c.margin == c.margin ? fmt::format(" ({:+.2f})", c.margin) : std::string();
    h += fmt::format(
        "<tr class=\"{}\"><td><a href=\"#claim-{}\">{}</a></td><td>{}</td><td><b>{}</b>{}"
        "</td><td>{}</td></tr>\n",
        verdict_class(c), escape(c.id), escape(c.id), escape(c.ours), escape(c.verdict), margin,
        escape(c.why));
  }
  return h + "</table>\n";
}

}  // namespace

namespace {

// A rig of the user's: the page says which, and that the built-in rig's account does not apply.
std::string users_rig(const std::string& source) {
  return "<h2>The rig</h2>\n<p>This report runs <b>" + escape(source) +
         "</b>, not the built-in virtual rig, under the paper's conditions (the supply pressure "
         "and the total moving mass of each figure); Fig. 2 uses the paper's own model. The "
         "full scenario is at the end of this page.</p>\n";
}

}  // namespace

std::string report_html(const std::vector<FigureFiles>& figures, const std::vector<Claim>& claims,
                        const std::string& scenario_toml, const std::string& settings,
                        const std::string& rig_source, const std::vector<Claim>& paper_claims) {
  const std::string headline = claims_headline(count_claims(claims));
  // Under both judges the title says both counts; the paragraph keeps the strict breakdown.
  const std::string title =
      paper_claims.empty() ? headline.substr(0, headline.find(" ("))
                           : both_judges_headline(count_claims(claims), count_claims(paper_claims));
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
      "<title>pneumachaos: Kosaki &amp; Sano, " +
      escape(title) +
      "</title>\n<style>\n"
      "body{font-family:sans-serif;max-width:1250px;margin:2em auto;padding:0 1em;color:#222}\n"
      "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:.35em .6em;"
      "vertical-align:top}\n.agrees{background:#e3f4e3}.disagrees{background:#fbe3e3}"
      ".not{background:#f1f1f1}\nfigure{margin:1.5em 0}img{max-width:100%;border:1px solid #ddd}\n"
      "pre{background:#f6f6f6;padding:1em;overflow:auto;font-size:85%}\n</style>\n"
      "<link rel=\"stylesheet\" href=\"report.css\"></head><body>\n"
      "<h1>An analytical and experimental study of chaotic oscillation in a pneumatic cylinder: "
      "the claims tested &mdash; " +
      escape(title) + "</h1>\n<p><b>" + escape(headline) + ".</b> " +
      (paper_claims.empty() ? std::string()
                            : "<b>" + escape(title) +
                                  "</b> (<a href=\"#paper-judge\">the chaos "
                                  "claims under the paper's judge</a>). ") +
      "Kosaki &amp; San&#333;'s figures and claims, computed by pneumachaos from " +
      (rig_source.empty() ? std::string("its built-in virtual rig") : escape(rig_source)) +
      "; each claim quotes the paper, says how we read it and is judged by a "
      "stated rule with a signed margin (&ge; 0 passes; <code>claims.json</code> holds the same "
      "table). " +
      escape(settings) + "</p>\n" +
      (rig_source.empty() ? std::string(kVirtualRig) : users_rig(rig_source)) +
      "<h2>The paper's claims against our numbers</h2>\n<p>The paper contradicts itself on the "
      "stick-slip region under a higher supply pressure (a decrease of about 20 % and, two "
      "sentences later, an extension): that row shows both sentences and is not scored; the "
      "chaos, on which both sentences agree, is. A rule that no plausible model could fail is "
      "marked <em>identity</em> and not scored either.</p>\n" +
      claims_table(claims) + paper_judge_table(paper_claims) + explanations_html() + kExplore;
  h += "<h2>Figures</h2>\n<p>Each figure's data, its gnuplot commands "
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
  h += "<h2>The scenario of the maps</h2>\n<p>Fig. 4's scenario, as the sweeps ran it (Figs. "
       "5 and 6 change only Ps or m; the example and Figs. 3 and 7 run it without scatter or "
       "texture).</p>\n<pre>" +
       escape(scenario_toml) +
       "</pre>\n<script src=\"report_data.js\"></script>\n"
       "<script src=\"report_charts.js\"></script>\n"
       "<script src=\"report.js\"></script>\n</body></html>\n";
  return h;
}

}  // namespace pneumachaos
