function list = options(name)
% OPTIONS  The options a fogdrift function takes, as the command line and Python describe them.
%
%   list = fogdrift.options('train')
%
%   name is train, simulate-calibration, simulate-northfind, evaluate, denoise or stream (the
%   fault policy of Model.exportC). list is a struct array: name, type, default, unit, allowed,
%   help, flag (the command line's).
[err, warns, list] = fogdrift_mex('options', name);
if ~isempty(err), error(err); end
end
