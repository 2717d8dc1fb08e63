"""fogdrift: start-up drift compensation for fiber-optic gyroscopes, and its ε-SVR engine.

The package wraps fogdrift's C++ library (docs/python.md):

* ``fogdrift.SVR`` — a scikit-learn regressor with LIBSVM's solution, several times faster,
  with warm-started C paths (``fit_path``) and threaded prediction (``n_jobs``).
* ``fogdrift.release_memory()`` — fits keep their kernel-row memory for the next fit in the
  process (about ``cache_size`` per thread that fits); this gives it back and returns the bytes.
"""
from ._fogdrift import __version__, release_memory
from .svr import SVR

__all__ = ["SVR", "release_memory", "__version__"]
