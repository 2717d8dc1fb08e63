% The drift workflow in Octave against the command line (octave_workflow, docs/matlab.md): the
% campaign fogdrift.simulate writes, the model fogdrift.train writes and the header exportC
% writes are the CLI's bytes with the same options; Model.predict's drift is compensate's to
% the bit; options come from the same tables and are refused by name. FOGDRIFT_CLI and
% FOGDRIFT_MATLAB_DIR are set by CTest.
1;
function run_cli(varargin)
  cmd = ['"' getenv('FOGDRIFT_CLI') '"' sprintf(' %s', varargin{:}) ' > cli_out.txt 2>&1'];
  [status, out] = system(cmd);
  if status ~= 0, error('test:cli', '%s failed: %s', cmd, fileread('cli_out.txt')); end
end

function text = fileread_cli(args)
  run_cli(args);
  text = fileread('cli_out.txt');
end

function same = same_bytes(a, b)
  same = strcmp(fileread(a), fileread(b));
end


addpath(getenv('FOGDRIFT_MATLAB_DIR'));
addpath(getenv('FOGDRIFT_MATLAB_TESTS'));  % check, expect_error
manifest = fogdrift.simulate('calibration', 'out', 'cal_m', 'seed', 4, 'temps_degc', [-20 0 20 40], ...
                             'repetitions', 2, 'powered_s', 1200);
run_cli('simulate calibration --out cal_c --seed 4 --temps=-20,0,20,40 --repetitions 2 --powered-s 1200');
names = {manifest.recordings.file};
check(numel(names) == 8, 'simulate returns the manifest with its recordings');
same = same_bytes('cal_m/campaign.json', 'cal_c/campaign.json');
for k = 1:numel(names)
  same = same && same_bytes(['cal_m/' names{k}], ['cal_c/' names{k}]);
end
check(same, 'simulate writes the CLI''s campaign byte for byte');

[model, summary] = fogdrift.train('cal_m', 'population', 8, 'iterations', 5, 'differentiator', 'causal', ...
                                  'out', 'model_m.json', 'progress', false);
run_cli('train cal_c --population 8 --iterations 5 --differentiator causal -o model_c.json --json');
check(same_bytes('model_m.json', 'model_c.json'), 'train writes the CLI''s model byte for byte');
cli = jsondecode(fileread('cli_out.txt'));
check(strcmp(summary.method, cli.method) && abs(summary.fitness_rmse - cli.fitness_rmse) <= 1e-15 * cli.fitness_rmse && ...
      summary.hyperparameters.C == cli.hyperparameters.C && summary.training_rows == cli.training_rows, ...
      'the summary is train --json''s');
check(isa(model, 'fogdrift.Model') && strcmp(model.info().target, 'gyro_dph') && model.info().causal, ...
      'train returns a fogdrift.Model');
model.save('model_s.json');
check(same_bytes('model_s.json', 'model_c.json'), 'Model.save writes the same bytes');
loaded = fogdrift.Model.load('model_c.json');
check(strcmp(loaded.text, model.text), 'Model.load reads them back');

rec = ['cal_c/' names{end}];
run_cli('compensate model_c.json', rec, '-o comp_c.csv');
c = csvread('comp_c.csv', 1, 0);
header = strsplit(strtrim(fgetl(fopen('comp_c.csv'))), ',');
drift_cli = c(:, strcmp(header, 'drift_dph'));
p = model.predict(fogdrift.read_recording(rec));
check(isequal(p.drift_dph, drift_cli), 'Model.predict''s drift is compensate''s to the bit');
fogdrift.compensate(model, rec, 'comp_m.csv');
check(same_bytes('comp_m.csv', 'comp_c.csv'), 'compensate writes the CLI''s file byte for byte');
q = model.predict(rec);
check(isequal(q.drift_dph, p.drift_dph), 'predict takes a path as well as a struct');

model.exportC('model_m.h', 'stream_rate_hz', 1, 'prefix', 'unit7');
run_cli('export-c model_c.json -o model_c.h --stream-rate-hz 1 --prefix unit7');
check(same_bytes('model_m.h', 'model_c.h'), 'exportC writes export-c''s header byte for byte');

e = fogdrift.evaluate(model, 'cal_m');
run_cli('evaluate model_c.json cal_c --json');
ce = jsondecode(fileread('cli_out.txt'));
% Octave's jsondecode reads the CLI's shortest digits to within an ulp, not always exactly.
check(strcmp(e.verdict, ce.verdict) && abs(e.overall.rmse_dph - ce.overall.rmse_dph) <= 1e-15 * ce.overall.rmse_dph, ...
      'evaluate gives evaluate --json''s figures');

x = sin((1:512)' / 20) + 0.1 * randn(512, 1);
[y, s] = fogdrift.denoise(x, 'wavelet', 'db4', 'threshold', 'universal');
check(isequal(size(y), size(x)) && s.level > 0 && std(y - x) < 0.2, 'denoise');
o = fogdrift.options('train');
check(any(strcmp({o.keyword}, 'c_max')) && any(strcmp({o.flag}, '--c-max')), 'options lists the table');
cli_o = jsondecode(fileread_cli('options train --json'));
check(isequal({o.keyword}, {cli_o.keyword}) && isequal({o.doc}, {cli_o.doc}), 'options are `fogdrift options --json`''s');
expect_error(@() fogdrift.options('trian'), 'fogdrift:badOption', 'option function: ''trian'' is not one of train', 'an unknown function named');

expect_error(@() fogdrift.train('cal_m', 'c_max', -1), 'fogdrift:badOption', 'option c_max:', 'a range named by keyword');
expect_error(@() fogdrift.train('cal_m', 'cmax', 1), 'fogdrift:badOption', 'is not an option of fogdrift.train', 'an unknown name');
expect_error(@() fogdrift.train('cal_m', 'population', 'many'), 'fogdrift:badOption', 'option population: must be a number', 'a word for a number');
expect_error(@() fogdrift.train('cal_m', 'population'), 'fogdrift:badInput', 'name–value pairs', 'a name without its value');
expect_error(@() fogdrift.train('nowhere'), 'fogdrift:badInput', 'nowhere', 'a missing campaign');
system(sprintf('"%s" simulate --print-instrument > cal_c/unit.json', getenv('FOGDRIFT_CLI')));
expect_error(@() fogdrift.simulate('calibration', 'out', 'cal_c', 'replace', true, 'instrument', 'cal_c/unit.json'), ...
             'fogdrift:badOption', 'holds cal_c/unit.json', 'a campaign replaced over the instrument file it reads');
check(exist('cal_c/unit.json', 'file') == 2, 'the instrument file is still there');
expect_error(@() fogdrift.simulate('calibration', 'out', 'cal_m'), 'fogdrift:badInput', '''replace'', true', 'a full folder is not replaced');
expect_error(@() model.predict(struct('time_s', [1; 2])), 'fogdrift:badInput', 'missing required column gyro_dph', 'a recording without its gyro');
expect_error(@() model.exportC('x.h', 'prefix', '7up'), 'fogdrift:badOption', 'prefix', 'a prefix C cannot use');
expect_error(@() fogdrift.Model('{"format": 1}'), 'fogdrift:badInput', 'model', 'a model text that is not one');
expect_error(@() fogdrift.compensate(model, rec, rec), 'fogdrift:badOption', 'which this call reads', 'an output that is its input');
expect_error(@() fogdrift.train('cal_m', 'population', 5, 'iterations', 1, 'out', ['cal_m/' names{1}]), ...
             'fogdrift:badOption', 'option out:', 'a model written over a recording');
expect_error(@() fogdrift.compensate(model, 'comp_c.csv', 'x.csv'), 'fogdrift:badInput', 'already has a drift_dph column', 'a compensated file again');
check(~exist('x.h', 'file') && ~exist('x.csv', 'file'), 'nothing is written on an error');
printf('all passed\n');
