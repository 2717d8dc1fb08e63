function [model, summary] = train(campaign, varargin)
% TRAIN  Trains a compensation model on a campaign's training recordings.
%
%   [model, summary] = fogdrift.train('cal', NAME, VALUE, ...)
%
%   campaign is a folder (or its campaign.json) written by fogdrift.simulate, `fogdrift
%   campaign` or by hand (docs/formats.md). model is a fogdrift.Model; summary a struct with
%   the method, hyperparameters, fitness, the search, the held-out estimate and warnings, the
%   fields `fogdrift train --json` prints. With 'out', the model file is written as well, the
%   bytes `fogdrift train CAMPAIGN -o FILE` writes with the same options. Advice on a weak
%   model is raised as a warning (fogdrift:train). Ctrl-C stops a search in Octave.
%
%   fogdrift's own names:
%   'out'       model file to write (atomically)
%   'threads'   threads, 0 for one per core (default 0); the model does not depend on it
%   'target'    the column to compensate (default 'gyro_dph'; 'gyro_y_dph', 'accel_x_g', ...)
%   'progress'  a line every 5 s of a search (default true)
%
%   The options of `fogdrift train`, by the names Python uses:
%   {options:train}
%
%   See also fogdrift.Model, fogdrift.evaluate, fogdrift.simulate.
[err, warns, text, summary] = fogdrift_mex('train', campaign, varargin{:});
if ~isempty(err), error(err); end
for k = 1:numel(warns), warning('fogdrift:train', '%s', warns{k}); end
model = fogdrift.Model(text);
end
