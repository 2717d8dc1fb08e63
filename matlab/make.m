function make(build_dir, out_dir)
% MAKE  Builds fogdrift for MATLAB (or Octave) with the host's own mex command.
%
%   make('/path/to/fogdrift/build')             % into BUILD/matlab-mex
%   make(build_dir, out_dir)
%   addpath(out_dir)                            % then fogdrift.* as in docs/matlab.md
%
%   build_dir is a CMake build of fogdrift's library, position-independent: the README's build
%   is when Octave or Python is built with it; otherwise configure with
%   -DCMAKE_POSITION_INDEPENDENT_CODE=ON and build the target fogdrift. mex needs a C++20
%   compiler (MATLAB: mex -setup C++) and the fmt and nlohmann-json headers. The sources are
%   those CMake builds for Octave (matlab/src); Ctrl-C reaches a long call in Octave only.
%   The functions' help lists no options here: fogdrift.options('train') does.
  here = fileparts(mfilename('fullpath'));
  root = fileparts(here);
  if nargin < 2, out_dir = fullfile(build_dir, 'matlab-mex'); end
  if ~exist(out_dir, 'dir'), mkdir(out_dir); end
  names = {'drift_commands', 'gateway', 'model_commands', 'mx_convert', 'svm_commands'};
  sources = cellfun(@(n) fullfile(here, 'src', [n '.cpp']), names, 'UniformOutput', false);
  common = {['-I' fullfile(root, 'include')], ['-I' fullfile(here, 'src')], sources{:}, ...
            ['-L' fullfile(build_dir, 'src')], '-lfogdrift', '-lfmt'};
  if exist('OCTAVE_VERSION', 'builtin')
    mex('-std=c++20', '-o', fullfile(out_dir, 'fogdrift_mex'), common{:});
  else
    mex('CXXFLAGS=$CXXFLAGS -std=c++20', '-output', 'fogdrift_mex', '-outdir', out_dir, common{:});
  end
  package = fullfile(out_dir, '+fogdrift');
  if ~exist(package, 'dir'), mkdir(package); end
  files = dir(fullfile(here, '+fogdrift', '*.m'));
  for k = 1:numel(files)
    text = fileread(fullfile(files(k).folder, files(k).name));
    text = regexprep(text, '%\s*\{options:([a-z-]+)\}', '%   fogdrift.options(''$1'') lists them.');
    f = fopen(fullfile(package, files(k).name), 'w');
    fwrite(f, text);
    fclose(f);
  end
end
