# cmake -DFILE=out.json -P check_json_keys.cmake: fails unless the analysis JSON has the keys
# the sweep and report read, each number with its unit.
file(READ "${FILE}" json)
foreach(path "lyapunov;wolf;value" "lyapunov;wolf;unit" "lyapunov;divergence;value"
             "lyapunov;divergence;uncertainty" "lyapunov;divergence;unit" "verdict;regime"
             "verdict;chaotic" "verdict;stick_slip" "zero_one;run" "zero_one;K;value"
             "zero_one;K;unit" "zero_one;K_q25;value" "zero_one;K_q75;value" "zero_one;step;unit"
             "surrogate;run" "surrogate;count" "surrogate;rank" "surrogate;p_value;value"
             "surrogate;null_rejected" "surrogate;statistic;value" "prediction;ratio;value"
             "verdict;seed_agreement;seeds" "verdict;seed_agreement;share")
  string(JSON value ERROR_VARIABLE err GET "${json}" ${path})
  if(err)
    message(FATAL_ERROR "missing key ${path}: ${err}")
  endif()
endforeach()
string(JSON unit GET "${json}" lyapunov divergence unit)
if(NOT unit STREQUAL "1/s")
  message(FATAL_ERROR "lyapunov.divergence.unit is '${unit}', expected 1/s")
endif()
message(STATUS "all keys present")
