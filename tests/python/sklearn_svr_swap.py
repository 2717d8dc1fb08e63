"""A pytest plugin that puts fogdrift.SVR where scikit-learn's own tests take sklearn.svm.SVR
(loaded before they are imported, so that `svm.SVR`, `from sklearn.svm import SVR` and their
parametrisations all get fogdrift's). Used by test_sklearn_suite.py."""
import sklearn.svm

import fogdrift

sklearn.svm.SVR = fogdrift.SVR
