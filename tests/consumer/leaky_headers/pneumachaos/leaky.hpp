#pragma once
// A public header that includes a header which is not installed: the header check
// (tests/consumer/headers) must fail on it (test packaging.headers_catch_internal).
#include "pneumachaos/internal_only.hpp"
