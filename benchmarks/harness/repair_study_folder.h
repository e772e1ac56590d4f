// A repair study's folder summarised again from its runs alone: each
// model's summary.md and summary.json tables, and its plots, rewritten by
// analyse_repair_study from runs.json, so that a change to the analysis
// (intention to treat, issue 43) reaches committed runs without running
// them again. What the runs alone cannot give (summary.md's head: the
// options and the run's extras; summary.json's "options" and the extras)
// is kept from the files as they were.
#pragma once

#include <string>

#include "stats/paired_comparison.h"

namespace alplan::bench {

// `model_dir` holds runs.json and summary.json (written by bench repair).
// Throws std::runtime_error naming the file when one cannot be read or
// written.
void summarise_study_folder(const std::string& model_dir, const stats::BootstrapOptions& bootstrap);

}  // namespace alplan::bench
