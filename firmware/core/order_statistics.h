// Medians of the small arrays the core keeps (a few recent inter-beat
// intervals, a few recent signal envelopes), by insertion sort: for the sizes
// used here (at most a few dozen) it is the smallest code and needs no heap.
#pragma once

#include <stddef.h>

namespace alplan::firmware {

// Sorts values[0..count) ascending in place.
void sort_ascending(float* values, size_t count);

// The median of values[0..count), reordering them; the mean of the two middle
// values for even counts; 0 for count == 0.
float median_in_place(float* values, size_t count);

}  // namespace alplan::firmware
