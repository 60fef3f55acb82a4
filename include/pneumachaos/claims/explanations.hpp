#pragma once
// The page's section "What could explain the paper's chaos": each explanation tested, how, its
// evidence and its status. The evidence comes from optimizer runs and record sets outside the
// report (their commands: docs/notes/virtual_rig.md), so the section states them as measured
// there rather than computing them again.

#include <string>

namespace pneumachaos {

/// The section as HTML, from its heading to its table's end.
std::string explanations_html();

}  // namespace pneumachaos
