function model = svmtrain(varargin)
% SVMTRAIN  epsilon-SVR with LIBSVM's MATLAB calling convention, on fogdrift's engine.
%
%   model = fogdrift.svmtrain(training_label_vector, training_instance_matrix, 'libsvm_options')
%   mse   = fogdrift.svmtrain(y, X, '-v 5 ...')
%
%   As LIBSVM's svmtrain: y is an m-by-1 double vector, X an m-by-n double matrix (dense or
%   sparse), the options svm-train's:
%     -s 3        epsilon-SVR, the only type (0, 1, 2 and 4 are refused by name)
%     -t 2 | 0    RBF exp(-gamma*|u-v|^2) (default) or linear u'*v (1, 3, 4 refused)
%     -g gamma    RBF gamma (default 1/number of features)
%     -c cost     C (default 1)
%     -p epsilon  epsilon of the insensitive tube (default 0.1)
%     -e tol      stopping tolerance (default 0.001)
%     -m MB       kernel cache (default 100)
%     -h 0 | 1    shrinking (default 1)
%     -v n        n-fold cross-validation: returns the mean squared error, not a model
%     -q          print nothing
%     -d, -r, -n  read and kept in Parameters as LIBSVM does; epsilon-SVR does not use them
%   and fogdrift's own:
%     --solver libsvm | pairs   libsvm (default): LIBSVM's working sets one for one, so the
%                               model is LIBSVM's; pairs: fogdrift's faster solver, the same
%                               optimum to the tolerance
%
%   The model is LIBSVM's struct (Parameters, nr_class, totalSV, rho, Label, sv_indices, ProbA,
%   ProbB, nSV, sv_coef, SVs), which LIBSVM's svmpredict reads too. -v folds are drawn by
%   fogdrift's generator (seed 1), not LIBSVM's rand(): the same every run, other than LIBSVM's.
%
%   Errors are MATLAB errors: fogdrift:badOption (an option named), fogdrift:badInput.
%
%   See also fogdrift.svmpredict, fogdrift.libsvmread.
[err, warns, model] = fogdrift_mex('svmtrain', varargin{:});
if ~isempty(err), error(err); end
for k = 1:numel(warns), warning('fogdrift:svmtrain', '%s', warns{k}); end
end
