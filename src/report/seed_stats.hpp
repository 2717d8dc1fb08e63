// What the report's JSON (paper_report.cpp) and its Markdown (paper_markdown.cpp) both compute
// over the seeds of a paper run. Private to src/report/.
#pragma once

#include <vector>

#include "fogdrift/report/paper_report.hpp"

namespace fogdrift::report {

/// Mean and SD over the seeds of `get(seed)`.
template <class Get>
MeanSd over_seeds(const PaperResult& r, Get get) {
  std::vector<double> v;
  for (const SeedRun& s : r.seeds) v.push_back(get(s));
  return mean_sd(v);
}

/// Whether every seed has Table 3 with the true drift subtracted.
bool has_oracle(const PaperResult& r);

}  // namespace fogdrift::report
