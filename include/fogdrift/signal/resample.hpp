// Block averaging to a coarser rate for modelling (docs/method.md §2; the SVR trains on 10 s means
// of the 1 Hz recording, which cuts the sample count tenfold and the white noise by sqrt(10)).
//
// Consecutive blocks of B = block_s / dt samples are replaced by their mean; the block's time is
// the mean of its sample times (the block centre). A trailing partial block (fewer than B samples
// at the end of a recording) is dropped: its mean would carry more noise than the others and sit
// at a different time offset, and it holds less than one block of data.
#pragma once

#include <span>
#include <vector>

namespace fogdrift::signal {

struct BlockAverageOptions {
  /// Block length, seconds; a whole multiple of the sample interval (to 1e-6 relative), > 0.
  double block_s = 10.0;
};

/// Samples per block, B = block_s / dt_s. Throws OptionError("block_s", ...) if block_s is not
/// positive, not a whole multiple of dt_s, or dt_s is not positive.
std::size_t block_samples(const BlockAverageOptions& options, double dt_s);

/// Means of consecutive blocks of `block` samples; the trailing partial block is dropped.
/// Returns floor(x.size() / block) values. Throws OptionError if block is 0.
std::vector<double> block_average(std::span<const double> x, std::size_t block);

}  // namespace fogdrift::signal
