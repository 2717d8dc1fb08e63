// How the denoising settings trade drift kept against noise left, on simulated start-up
// recordings whose true thermal drift is known (the simulator's drift_true_dph column). The
// defaults of signal::DenoiseOptions were chosen from this table (docs/signal.md).
//
//   build/bench/denoise_study [--seeds N]
//
// For every recording of N one-repetition calibration campaigns (seeds 1..N, default 5;
// −40 … 60 °C, 30 min at 1 Hz, so 11 N recordings):
//   e = denoised gyro − Earth rate − true drift, minus its mean (the turn-on bias)
//   noise left  = RMS(e), °/h, at 1 Hz and of 10 s block means
//   drift kept  = least-squares slope of (denoised − mean) on (true drift − mean); 1 = all kept
// and the medians over recordings are printed as a Markdown table, best residual first.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "fogdrift/base/earth.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/signal/denoise.hpp"
#include "fogdrift/signal/resample.hpp"
#include "fogdrift/sim/scenarios.hpp"

namespace {

using namespace fogdrift;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double centred_rms(const std::vector<double>& e) {
  double mean = 0;
  for (double v : e) mean += v / double(e.size());
  double ss = 0;
  for (double v : e) ss += (v - mean) * (v - mean);
  return std::sqrt(ss / double(e.size()));
}

struct Row {
  std::string setting;
  double rms_1hz, rms_10s, kept;
};

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t seeds = 5;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--seeds") == 0) seeds = std::stoull(argv[i + 1]);
  }
  sim::CalibrationOptions o;
  o.repetitions = 1;
  o.test_repetitions = 0;
  sim::SimulatedCampaign campaign;
  for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
    o.seed = seed;
    auto c = sim::simulate_calibration(sim::Instrument{}, o);
    for (auto& r : c.recordings) campaign.recordings.push_back(std::move(r));
  }
  const double earth = kEarthRateDph * std::cos(o.latitude_deg * 3.14159265358979323846 / 180.0);

  std::vector<signal::DenoiseOptions> settings;
  for (const char* w : {"db1", "db4", "sym4", "sym8", "coif3", "db10"}) {
    for (auto rule : {signal::ThresholdRule::universal, signal::ThresholdRule::level,
                      signal::ThresholdRule::sure, signal::ThresholdRule::bayes}) {
      for (auto shrink : {signal::Shrinkage::soft, signal::Shrinkage::hard}) {
        for (int level : {0, 4, 6, 8}) {
          signal::DenoiseOptions d;
          d.wavelet = w;
          d.threshold = rule;
          d.shrinkage = shrink;
          if (level > 0) d.level = level;
          try {
            signal::validate(d, static_cast<std::size_t>(o.powered_s * o.output_rate_hz));
          } catch (const OptionError&) {
            continue;  // too deep for a 30-min recording with this wavelet
          }
          settings.push_back(d);
        }
      }
    }
  }
  std::vector<Row> rows;
  // The raw gyro, for scale.
  {
    std::vector<double> r1, r10;
    for (const auto& rec : campaign.recordings) {
      const auto truth = rec.numeric_column("drift_true_dph");
      std::vector<double> e(rec.size());
      for (std::size_t i = 0; i < e.size(); ++i) e[i] = rec.gyro_dph[i] - earth - truth[i];
      r1.push_back(centred_rms(e));
      r10.push_back(centred_rms(signal::block_average(e, 10)));
    }
    rows.push_back({"raw gyro (no denoising)", median(r1), median(r10), 1.0});
  }
  for (const auto& d : settings) {
    std::vector<double> r1, r10, kept;
    for (const auto& rec : campaign.recordings) {
      const auto truth = rec.numeric_column("drift_true_dph");
      const auto den = signal::denoise(rec.gyro_dph, d).signal;
      std::vector<double> e(rec.size());
      double mt = 0, md = 0;
      for (std::size_t i = 0; i < e.size(); ++i) {
        e[i] = den[i] - earth - truth[i];
        mt += truth[i] / double(e.size());
        md += den[i] / double(e.size());
      }
      double sxy = 0, sxx = 0;
      for (std::size_t i = 0; i < e.size(); ++i) {
        sxy += (truth[i] - mt) * (den[i] - md);
        sxx += (truth[i] - mt) * (truth[i] - mt);
      }
      r1.push_back(centred_rms(e));
      r10.push_back(centred_rms(signal::block_average(e, 10)));
      kept.push_back(sxy / sxx);
    }
    const std::string level = d.level ? std::to_string(*d.level) : "max";
    rows.push_back({d.wavelet + " " + std::string(to_string(d.threshold)) + " " +
                        std::string(to_string(d.shrinkage)) + " level " + level,
                    median(r1), median(r10), median(kept)});
  }
  std::sort(rows.begin() + 1, rows.end(),
            [](const Row& a, const Row& b) { return a.rms_10s < b.rms_10s; });
  std::printf("| setting | noise left, 1 Hz (°/h) | noise left, 10 s means (°/h) | drift kept |\n");
  std::printf("|---|---|---|---|\n");
  for (const auto& r : rows) {
    std::printf("| %s | %.5f | %.5f | %.3f |\n", r.setting.c_str(), r.rms_1hz, r.rms_10s, r.kept);
  }
  return 0;
}
