function [predicted_label, accuracy, decision_values] = svmpredict(varargin)
% SVMPREDICT  Predictions of an epsilon-SVR model, LIBSVM's MATLAB calling convention.
%
%   [predicted_label, accuracy, decision_values] = ...
%       fogdrift.svmpredict(testing_label_vector, testing_instance_matrix, model, 'libsvm_options')
%
%   model is the struct fogdrift.svmtrain or LIBSVM's svmtrain returned (epsilon- or nu-SVR,
%   RBF or linear kernel). accuracy is [accuracy in %; mean squared error; squared correlation
%   coefficient], as LIBSVM's; decision_values are the predictions. Options: -q (print nothing),
%   -b 0 (-b 1, probability estimates, is refused). Features the model never saw count as zero,
%   LIBSVM's rule.
%
%   See also fogdrift.svmtrain.
[err, warns, predicted_label, accuracy, decision_values] = fogdrift_mex('svmpredict', varargin{:});
if ~isempty(err), error(err); end
for k = 1:numel(warns), warning('fogdrift:svmpredict', '%s', warns{k}); end
end
