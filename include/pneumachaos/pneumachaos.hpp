#pragma once
// The public C++ API in one include: scenarios and the plant, simulation and the model's own
// exponent, the steady motion's stability, the chaos analysis of a record, measured records
// and fits, S1 x S2 sweeps, the paper's claims, the report and calibration (docs/guide/cpp.md),
// and the writers of every result file the command line produces. The installed headers are exactly
// these and the ones they include; the implementation's own headers stay in src/
// (docs/architecture.md, "Public and internal headers").

#include "pneumachaos/analysis/analysis_output.hpp"
#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/analysis/regime.hpp"
#include "pneumachaos/calibrate/calibrate.hpp"
#include "pneumachaos/claims/example_run.hpp"
#include "pneumachaos/claims/explanations.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/time_series.hpp"
#include "pneumachaos/identify/fit.hpp"
#include "pneumachaos/identify/friction_estimate.hpp"
#include "pneumachaos/identify/friction_fits.hpp"
#include "pneumachaos/identify/friction_output.hpp"
#include "pneumachaos/identify/measured_record_csv.hpp"
#include "pneumachaos/io/atomic_file.hpp"
#include "pneumachaos/io/column_units.hpp"
#include "pneumachaos/io/csv_reader.hpp"
#include "pneumachaos/io/csv_writer.hpp"
#include "pneumachaos/model/parameter_grid.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/scenario.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/model/variation.hpp"
#include "pneumachaos/report/reproduce.hpp"
#include "pneumachaos/simulate/lyapunov_output.hpp"
#include "pneumachaos/simulate/measured_channels.hpp"
#include "pneumachaos/simulate/model_lyapunov.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "pneumachaos/stability/stability_analysis.hpp"
#include "pneumachaos/stability/stability_map.hpp"
#include "pneumachaos/stability/stability_output.hpp"
#include "pneumachaos/sweep/sweep.hpp"
#include "pneumachaos/sweep/sweep_runner.hpp"
