function recording = read_recording(path)
% READ_RECORDING  A recording CSV (docs/formats.md) as a struct of column vectors.
%
%   r = fogdrift.read_recording('cal/rec_01.csv');  plot(r.time_s, r.gyro_dph)
%
%   Errors name the file, line and column (fogdrift:badInput).
[err, warns, recording] = fogdrift_mex('read_recording', path);
if ~isempty(err), error(err); end
end
