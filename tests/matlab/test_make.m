% matlab/make.m, the build for MATLAB users, run here with Octave's own mex (octave_make): the
% MEX file it builds from the same sources fits the command line's model, and its package's help
% points at fogdrift.options. FOGDRIFT_SOURCE_DIR, FOGDRIFT_BUILD_DIR, FOGDRIFT_CLI and
% FOGDRIFT_MATLAB_TESTS are set by CTest.
addpath(getenv('FOGDRIFT_MATLAB_TESTS'));  % check
addpath(fullfile(getenv('FOGDRIFT_SOURCE_DIR'), 'matlab'));
made = fullfile(pwd, 'made');
make(getenv('FOGDRIFT_BUILD_DIR'), made);
check(numel(dir(fullfile(made, ['fogdrift_mex.' mexext()]))) == 1, 'make builds fogdrift_mex');
addpath(made);
check(strcmp(fileparts(which('fogdrift_mex')), made), 'the MEX file made is the one called');
X = [linspace(-2, 2, 80)', cos(linspace(0, 3, 80))'];
y = sin(2 * X(:, 1)) + 0.3 * X(:, 2);
model = fogdrift.svmtrain(y, X, '-c 10 -g 0.5 -p 0.05 -q');
% The command line's fit of the same data, same options, LIBSVM's working sets (fogdrift svr).
f = fopen('data.txt', 'w');
fprintf(f, '%.17g 1:%.17g 2:%.17g\n', [y, X]');
fclose(f);
cmd = sprintf('"%s" svr train --solver libsvm -q -c 10 -g 0.5 -p 0.05 data.txt cli.json', ...
              getenv('FOGDRIFT_CLI'));
check(system(cmd) == 0, 'the command line fits the same data');
cli = jsondecode(fileread('cli.json'));
% To an ulp: Octave's jsondecode reads the shortest digits the CLI writes to within one.
check(max(abs(model.sv_coef - cli.coef(:)) ./ abs(cli.coef(:))) <= 1e-15 && ...
      abs(model.rho - cli.rho) <= 1e-15 * abs(cli.rho), ...
      'the same model as the command line''s, coefficient for coefficient');
[p, acc] = fogdrift.svmpredict(y, X, model, '-q');
check(acc(2) < 0.01, 'a model that fits');
text = evalc('help fogdrift.train');
check(~isempty(strfind(text, 'fogdrift.options(''train'') lists them')), 'help points at fogdrift.options');
o = fogdrift.options('train');
check(numel(o) > 20, 'fogdrift.options lists train''s options');
printf('all passed\n');
