#pragma once
// A self-contained header beside the leaky one: only leaky.hpp may be reported.
#include <vector>
inline std::vector<int> fine() { return {1}; }
