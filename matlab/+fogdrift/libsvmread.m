function [label_vector, instance_matrix] = libsvmread(filename)
% LIBSVMREAD  Reads a LIBSVM-format data file, as LIBSVM's libsvmread.
%
%   [label_vector, instance_matrix] = fogdrift.libsvmread('data.txt')
%
%   instance_matrix is sparse. A malformed line is an error naming the file, line and column
%   (fogdrift:badInput).
%
%   See also fogdrift.svmtrain.
[err, warns, label_vector, instance_matrix] = fogdrift_mex('libsvmread', filename);
if ~isempty(err), error(err); end
end
