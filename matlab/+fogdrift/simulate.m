function manifest = simulate(scenario, varargin)
% SIMULATE  Simulates a campaign of recordings on fogdrift's built-in instrument.
%
%   manifest = fogdrift.simulate('calibration', 'out', 'cal', 'seed', 1, NAME, VALUE, ...)
%
%   scenario is 'calibration' (the chamber campaign a model is trained on), 'northfind' or
%   'stable'. The campaign is written to the folder 'out' (campaign.json and one CSV per
%   recording), the files `fogdrift simulate SCENARIO --out FOLDER --seed SEED` writes, byte for
%   byte; manifest is campaign.json as a struct.
%
%   fogdrift's own names:
%   'out'         folder to write (none: nothing is written)
%   'seed'        random seed, a whole number (default 1); the same seed gives the same files
%   'instrument'  a JSON file of the simulated instrument (fogdrift simulate --print-instrument)
%   'replace'     true to replace a folder that holds an earlier campaign (default false)
%
%   The calibration's options ('northfind' and 'stable' take those of `fogdrift options
%   simulate-northfind`):
%   {options:simulate-calibration}
%
%   See also fogdrift.train.
[err, warns, manifest] = fogdrift_mex('simulate', scenario, varargin{:});
if ~isempty(err), error(err); end
for k = 1:numel(warns), warning('fogdrift:simulate', '%s', warns{k}); end
end
