// Corrections for a family of tests: each study that tests several
// hypotheses at once (strategies against a reference, tables of observation
// kinds) adjusts the family's p-values with one of these before calling a
// difference significant. Both return the adjusted p in the given order.
#pragma once

#include <vector>

namespace alplan::stats {

// Holm's (1979) step-down adjustment of a family's p-values, returned in
// the given order: with the p sorted ascending, p_(i) becomes
// max over j <= i of min(1, (m - j + 1) p_(j)). Rejecting where the adjusted
// p is below alpha controls the family-wise error rate at alpha.
std::vector<double> holm_adjust(const std::vector<double>& p);

// Benjamini & Hochberg's (1995, JRSS B 57:289) step-up adjustment: with the
// p sorted ascending, p_(i) becomes min over j >= i of min(1, m p_(j) / j).
// Rejecting where the adjusted p is below q controls the false discovery
// rate at q for independent or positively dependent tests.
std::vector<double> benjamini_hochberg_adjust(const std::vector<double>& p);

}  // namespace alplan::stats
