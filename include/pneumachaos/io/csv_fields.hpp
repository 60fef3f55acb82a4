#pragma once
// The one splitter of a comma-separated line, shared by the record reader and the sweep
// journal: fields as written (no trimming, no quotes), an empty last field kept.

#include <string>
#include <vector>

namespace pneumachaos {

std::vector<std::string> split_csv_fields(const std::string& line);

}  // namespace pneumachaos
