function summary = compensate(model, input, output, varargin)
% COMPENSATE  Writes a recording with the model's drift subtracted, as `fogdrift compensate`.
%
%   summary = fogdrift.compensate(model, 'cal/cal_r4_20C.csv', 'comp.csv')
%   summary = fogdrift.compensate(model, input, output, 'guarded', false)
%
%   model is a fogdrift.Model or a model file's path. output holds every column of input as it
%   was written, then drift_dph, gyro_comp_dph, novelty and guard_weight (a model of another
%   target names them in its unit): the bytes `fogdrift compensate MODEL INPUT -o OUTPUT`
%   writes, written atomically. 'guarded', false applies the correction in full where the
%   inputs are novel to the model. summary holds the samples, the columns added and the
%   novelty line.
%
%   See also fogdrift.Model.
if ischar(model), model = fogdrift.Model.load(model); end
[err, warns, summary] = fogdrift_mex('compensate', model.text, input, output, varargin{:});
if ~isempty(err), error(err); end
end
