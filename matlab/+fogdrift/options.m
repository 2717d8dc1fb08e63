function list = options(name)
% OPTIONS  The options a fogdrift function takes, as the command line and Python describe them.
%
%   list = fogdrift.options('train')
%
%   name is train, simulate-calibration, simulate-northfind, simulate-stable, evaluate, denoise,
%   northfind, paper or stream (the fault policy of Model.exportC). list is a struct array, as
%   `fogdrift options NAME --json` prints it: keyword (the name-value name), flag (the command
%   line's), type, unit, default, allowed, doc and help.
[err, warns, list] = fogdrift_mex('options', name);
if ~isempty(err), error(err); end
end
