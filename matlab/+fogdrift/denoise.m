function [y, summary] = denoise(x, varargin)
% DENOISE  Wavelet denoising of a signal, PyWavelets' conventions.
%
%   [y, summary] = fogdrift.denoise(x, NAME, VALUE, ...)
%
%   x is a real vector; y has its shape. summary holds the levels used, the noise sigma from
%   the finest band and each band's threshold and kept coefficients.
%
%   Options:
%   {options:denoise}
[err, warns, y, summary] = fogdrift_mex('denoise', x, varargin{:});
if ~isempty(err), error(err); end
end
