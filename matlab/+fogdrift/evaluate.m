function result = evaluate(model, campaign, varargin)
% EVALUATE  A model's Table 2 on a campaign, beside its baselines.
%
%   result = fogdrift.evaluate(model, 'cal', NAME, VALUE, ...)
%
%   model is a fogdrift.Model (or a model file's path); campaign a folder. result is the struct
%   of `fogdrift evaluate --json`: overall metrics, baselines, the verdict, each recording's
%   metrics. A model that harms a recording or is no better than its baselines raises a warning
%   (fogdrift:evaluate).
%
%   Options:
%   {options:evaluate}
%
%   See also fogdrift.train.
if ischar(model), model = fogdrift.Model.load(model); end
[err, warns, result] = fogdrift_mex('evaluate', model.text, campaign, varargin{:});
if ~isempty(err), error(err); end
for k = 1:numel(warns), warning('fogdrift:evaluate', '%s', warns{k}); end
end
