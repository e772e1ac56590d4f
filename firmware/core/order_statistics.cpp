#include "order_statistics.h"

namespace alplan::firmware {

void sort_ascending(float* values, size_t count) {
  for (size_t i = 1; i < count; ++i) {
    const float value = values[i];
    size_t j = i;
    while (j > 0 && values[j - 1] > value) {
      values[j] = values[j - 1];
      --j;
    }
    values[j] = value;
  }
}

float median_in_place(float* values, size_t count) {
  if (count == 0) return 0.0f;
  sort_ascending(values, count);
  const size_t middle = count / 2;
  if (count % 2 == 1) return values[middle];
  return 0.5f * (values[middle - 1] + values[middle]);
}

}  // namespace alplan::firmware
