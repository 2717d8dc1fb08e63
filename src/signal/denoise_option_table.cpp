// Wavelet denoising's options (denoise_option_table.hpp). Defaults are DenoiseOptions'; the wavelet
// and the level are checked against the signal by validate() (denoise.hpp), whose errors name
// each option by its keyword.
#include "fogdrift/signal/denoise_option_table.hpp"

#include <cstdint>
#include <limits>
#include <string>

namespace fogdrift::signal {
namespace {

OptionTable<DenoiseOptions> make_denoise_table() {
  using O = DenoiseOptions;
  OptionTable<O> t;
  t.push_back({{"wavelet",
                "--wavelet",
                OptionType::choice,
                "",
                "haar, db1 … db20, sym2 … sym20, coif1 … coif5",
                "Wavelet, by PyWavelets' name for its filters",
                {}},
               [](const O& o) { return o.wavelet; },
               [](O& o, const std::string& text) { o.wavelet = text; }});
  // "max" is the word this option had before it was described here; it stays a synonym of auto.
  OptionSpec level{
      "level",
      "--level",
      OptionType::whole_or_auto,
      "",
      at_least(1).with("at most floor(log2(N / (F − 1))) for N samples and a filter of F taps"),
      "Decomposition levels; auto (or max): the largest the signal allows, "
      "PyWavelets' default",
      {}};
  t.push_back(
      {level, [](const O& o) { return o.level ? std::to_string(*o.level) : std::string("auto"); },
       [level](O& o, const std::string& text) {
         if (text == "max") {
           o.level.reset();
           return;
         }
         const auto v = parse_whole_or_auto_option(level, text);
         if (v && *v > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
           throw OptionError("level", text + " is too high: it must be " + level.range.note);
         o.level = v ? std::optional<int>(static_cast<int>(*v)) : std::nullopt;
       }});
  t.push_back(choice_option<O>(
      {"threshold",
       "--threshold",
       {},
       "",
       threshold_rule_names(),
       "How each detail band's threshold is chosen: universal, σ √(2 ln N) on every band "
       "(VisuShrink); level, the same with σ of each band (coloured noise); sure, Stein's "
       "unbiased risk estimate per band (SureShrink); bayes, σ² / σ_signal per band (BayesShrink)",
       {}},
      [](auto& o) -> auto& { return o.threshold; }, [](ThresholdRule r) { return to_string(r); },
      [](const std::string& text, const std::string& keyword) {
        return parse_threshold_rule(text, keyword);
      }));
  t.push_back(choice_option<O>(
      {"mode",
       "--mode",
       {},
       "",
       shrinkage_names(),
       "Shrinkage of the coefficients: soft moves every one towards zero by the threshold, hard "
       "zeroes those below it (pywt.threshold's mode)",
       {}},
      [](auto& o) -> auto& { return o.shrinkage; }, [](Shrinkage s) { return to_string(s); },
      [](const std::string& text, const std::string& keyword) {
        return parse_shrinkage(text, keyword);
      }));
  t.push_back(choice_option<O>(
      {"extension",
       "--extension",
       {},
       "",
       extension_names(),
       "How the signal is extended beyond its ends (pywt.wavedec's mode)",
       {}},
      [](auto& o) -> auto& { return o.extension; }, [](Extension e) { return to_string(e); },
      [](const std::string& text, const std::string& keyword) {
        return parse_extension(text, keyword);
      }));
  return t;
}

}  // namespace

const OptionTable<DenoiseOptions>& denoise_option_table() {
  static const OptionTable<DenoiseOptions> table = make_denoise_table();
  return table;
}

}  // namespace fogdrift::signal
