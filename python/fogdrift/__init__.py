"""fogdrift: start-up drift compensation for fiber-optic gyroscopes, and its ε-SVR engine.

The package wraps fogdrift's C++ library (docs/python.md):

* ``fogdrift.SVR`` — a scikit-learn regressor with LIBSVM's solution, several times faster,
  with warm-started C paths (``fit_path``) and threaded prediction (``n_jobs``);
  ``fogdrift.SVRGridSearchCV`` is GridSearchCV for it, alone or ending a Pipeline, by
  warm-started paths over C in parallel, scored by any scorer.
* ``fogdrift.train(campaign, method=..., ...)`` — a campaign folder to a compensation model, as
  ``fogdrift train`` does it, every option under the library's name, with a progress callback;
  ``target=`` another gyro axis, an accelerometer or a scale-factor channel, and
  ``save_models`` every axis's model in one file;
* ``fogdrift.Model`` — a compensation model file as ``fogdrift train`` writes it: load, save,
  predict the drift of a recording and compensate it; ``read_recording`` and
  ``write_recording`` — recordings as dicts of NumPy arrays.
* ``simulate``, ``denoise``, ``features``, ``evaluate`` (Table 2), ``northfind`` (Table 3),
  ``find_north`` (the findings of one recording),
  ``allan_deviation`` and ``noise_terms``, ``StreamingCompensator`` — the rest of the pipeline,
  each as the command of the same name computes it.
* ``fogdrift.train_fleet(campaigns, client=...)`` — one model per unit's campaign, in parallel on
  a Dask cluster (``fogdrift.fleet``), the same bytes as a serial run.
* ``fogdrift.release_memory()`` — fits keep their kernel-row memory for the next fit in the
  process (about ``cache_size`` per thread that fits, and at most 1 GiB of blocks from fits and
  searches that ended); this gives it back and returns the bytes.
"""
from ._fogdrift import (Model, StreamingCompensator, __version__, allan_deviation, denoise,
                        denoise_options, evaluate, evaluate_options, features, find_north,
                        model_load_options, noise_terms, northfind, northfind_options, read_recording,
                        release_memory, save_models, sensed_options, simulate,
                        simulate_options, stream_options, train, train_options, write_recording)
from ._keywords import method_naming_keywords, naming_keywords
from ._options import keyword_lines, with_keywords, with_options
from ._progress import with_progress
from .fleet import train_fleet
from .search import SVRGridSearchCV
from .svr import SVR

# A wrong type is a TypeError naming the keyword, not the whole signature (_keywords.py).
(allan_deviation, denoise, evaluate, features, find_north, noise_terms, northfind, read_recording,
 save_models, simulate, write_recording) = (
    naming_keywords(f) for f in (allan_deviation, denoise, evaluate, features, find_north,
                                 noise_terms, northfind, read_recording, save_models, simulate,
                                 write_recording))
# train checks its keywords against the library's descriptions of them (docs/options.md); its
# signature and docstring come from the same descriptions (_options.py).
train = with_options(with_progress(train), train_options())
simulate.__doc__ += "".join(
    f"\n\nKeywords of {scenario}:\n" + "\n".join(
        keyword_lines(simulate_options(scenario), f"fogdrift simulate {scenario}"))
    for scenario in ("calibration", "northfind", "stable"))
# What the recordings' channels sensed (as evaluate --input-rate-dph and --reference), then the
# evaluation's own options: each from its one description.
evaluate = with_keywords(evaluate, ["model", "data"], sensed_options() + evaluate_options(),
                         "fogdrift evaluate")
northfind = with_keywords(northfind, ["campaign", ("model", None)], northfind_options(),
                          "fogdrift northfind")
find_north = with_keywords(find_north, ["recording", "latitude_deg", ("model", None)],
                           northfind_options(), "fogdrift northfind")
denoise = with_keywords(denoise, ["data"],
                        [dict(keyword="summary", default="false", type="on/off", flag="--json",
                              doc="Also return the level, the noise sigma and each band's "
                                  "threshold and coefficients kept")]
                        + denoise_options(), "fogdrift denoise")
for _method in ("__init__", "update", "run"):
    method_naming_keywords(StreamingCompensator, _method)
# Its signature and docstring show the guard's and the fault policy's keywords from their one
# description.
StreamingCompensator.__init__ = with_keywords(StreamingCompensator.__init__,
                                              ["self", "model", "dt_s"], stream_options(),
                                              "fogdrift stream")
for _method in ("predict", "compensate", "save", "to_json"):
    method_naming_keywords(Model, _method)
# allow_edited and allow_old_format, from the description of every command's --allow-edited
# and --allow-old-format.
Model.load = staticmethod(with_keywords(naming_keywords(Model.load, "Model.load"),
                                        ["path", ("target", None)], model_load_options(),
                                        "fogdrift compensate"))
Model.from_json = staticmethod(with_keywords(naming_keywords(Model.from_json, "Model.from_json"),
                                             ["text"], model_load_options(),
                                             "fogdrift compensate"))
del _method

__all__ = ["Model", "SVR", "SVRGridSearchCV", "StreamingCompensator", "allan_deviation",
           "denoise", "evaluate", "features", "find_north", "noise_terms", "northfind",
           "read_recording", "release_memory", "save_models", "simulate", "train", "train_fleet",
           "denoise_options", "evaluate_options", "model_load_options", "northfind_options",
           "sensed_options", "simulate_options", "stream_options", "train_options",
           "write_recording", "__version__"]
