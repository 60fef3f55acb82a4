// The report's section "What could explain the paper's chaos" (pneumachaos/claims/explanations.hpp).
#include <gtest/gtest.h>

#include <string>

#include "pneumachaos/claims/explanations.hpp"

namespace pneumachaos {
namespace {

// Five explanations, each a row whose status (its last cell) is one of the three the section
// promises (reproduces, ruled out within stated bounds, or untested) and whose test is a
// calibration.
TEST(Explanations, EveryRowEndsInOneOfTheThreeStatuses) {
  const std::string h = explanations_html();
  std::size_t rows = 0;
  for (std::size_t at = h.find("<tr><td>"); at != std::string::npos;
       at = h.find("<tr><td>", at + 1)) {
    ++rows;
    const std::size_t end = h.find("</td></tr>", at);
    const std::size_t last = h.rfind("<td>", end) + 4;
    const std::string status = h.substr(last, end - last);
    // Each explanation was tested with the optimizer: its row names a calibration.
    EXPECT_NE(h.substr(at, end - at).find("calibrate scenarios/calibrations/"), std::string::npos)
        << h.substr(at, 80);
    EXPECT_TRUE(status.starts_with("reproduces") || status.starts_with("ruled out") ||
                status.starts_with("untested"))
        << status;
  }
  EXPECT_EQ(rows, 5u);
  EXPECT_NE(h.find("id=\"explanations\""), std::string::npos);
}

}  // namespace
}  // namespace pneumachaos
