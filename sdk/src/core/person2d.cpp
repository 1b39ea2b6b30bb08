#include "core/person2d.h"

#include <algorithm>

namespace octocap::internal {

Person2D interpolate_person(const Person2D& a, const Person2D& b, double w, double min_conf) {
  if (a.empty() || b.empty() || a.size() != b.size()) return w < 0.5 ? a : b;
  Person2D out(a.size());
  for (size_t k = 0; k < a.size(); ++k) {
    if (a[k].confidence >= min_conf && b[k].confidence >= min_conf)
      out[k] = {a[k].x + w * (b[k].x - a[k].x), a[k].y + w * (b[k].y - a[k].y),
                std::min(a[k].confidence, b[k].confidence)};
    else
      out[k] = w < 0.5 ? a[k] : b[k];
  }
  return out;
}

}  // namespace octocap::internal
