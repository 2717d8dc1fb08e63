% fogdrift.svmtrain and fogdrift.svmpredict against LIBSVM's C API on the same data
% (tests/matlab/libsvm_reference.cpp): support vectors, coefficients, rho and predictions to
% 1e-12 relative, for RBF and linear kernels, dense and sparse input, with and without
% shrinking; LIBSVM's model struct; -v; refusals by identifier. Run by CTest (octave_svm) with
% FOGDRIFT_LIBSVM_REFERENCE set.
1;
function write_libsvm(path, y, X)
  f = fopen(path, 'w');
  for i = 1:numel(y)
    fprintf(f, '%.17g', y(i));
    for j = 1:size(X, 2)
      if X(i, j) ~= 0, fprintf(f, ' %d:%.17g', j, X(i, j)); end
    end
    fprintf(f, '\n');
  end
  fclose(f);
end

function ref = libsvm(y, X, Xt, c, gamma, p, kernel, shrinking)
  write_libsvm('ref_train.txt', y, X);
  write_libsvm('ref_test.txt', zeros(size(Xt, 1), 1), Xt);
  cmd = sprintf('"%s" ref_train.txt ref_test.txt %.17g %.17g %.17g %d %d > ref_out.txt', ...
                getenv('FOGDRIFT_LIBSVM_REFERENCE'), c, gamma, p, kernel, shrinking);
  [status, out] = system(cmd);
  if status ~= 0, error('test:reference', 'libsvm_reference failed: %s', out); end
  m = load('-ascii', 'ref_out.txt');
  ref.rho = m(1, 1);
  n = m(1, 2);
  ref.sv_indices = m(2:n + 1, 1);
  ref.sv_coef = m(2:n + 1, 2);
  ref.pred = m(n + 2:end, 1);
end

function r = rel(a, b)
  r = max(abs(a(:) - b(:)) ./ (1 + abs(b(:))));
end

addpath(getenv('FOGDRIFT_MATLAB_DIR'));
addpath(getenv('FOGDRIFT_MATLAB_TESTS'));  % check, expect_error
rand('twister', 5);
n = 240;
X = [rand(n, 1) * 4 - 2, rand(n, 1) * 2 - 1, (rand(n, 1) > 0.7) .* rand(n, 1)];
y = sin(2 * X(:, 1)) + 0.5 * X(:, 2) - X(:, 3) + 0.05 * randn(n, 1);
Xt = [rand(50, 1) * 4 - 2, rand(50, 1) * 2 - 1, zeros(50, 1)];
yt = sin(2 * Xt(:, 1)) + 0.5 * Xt(:, 2);

cases = {'-s 3 -t 2 -c 10 -g 0.8 -p 0.05 -q', 10, 0.8, 0.05, 2, 1; ...
         '-s 3 -t 2 -c 300 -g 2 -p 0.01 -h 0 -q', 300, 2, 0.01, 2, 0; ...
         '-s 3 -t 0 -c 1 -p 0.1 -q', 1, 1 / 3, 0.1, 0, 1};
for k = 1:rows(cases)
  [opts, c, gamma, p, kernel, shrinking] = cases{k, :};
  ref = libsvm(y, X, Xt, c, gamma, p, kernel, shrinking);
  for input = {X, sparse(X)}
    model = fogdrift.svmtrain(y, input{1}, opts);
    kind = 'dense';
    if issparse(input{1}), kind = 'sparse'; end
    check(isequal(model.sv_indices, ref.sv_indices), sprintf('%s (%s): the same support vectors', opts, kind));
    check(rel(model.sv_coef, ref.sv_coef) < 1e-12, sprintf('%s (%s): sv_coef to 1e-12', opts, kind));
    check(rel(model.rho, ref.rho) < 1e-12, sprintf('%s (%s): rho to 1e-12', opts, kind));
    check(isequal(full(model.SVs), X(ref.sv_indices, :)), sprintf('%s (%s): SVs are the training rows', opts, kind));
    [pred, acc, dec] = fogdrift.svmpredict(yt, Xt, model, '-q');
    check(rel(pred, ref.pred) < 1e-12, sprintf('%s (%s): predictions to 1e-12', opts, kind));
    check(isequal(pred, dec) && numel(acc) == 3 && abs(acc(2) - mean((pred - yt) .^ 2)) < 1e-15, ...
          sprintf('%s (%s): accuracy is [%%; MSE; r^2]', opts, kind));
  end
end

model = fogdrift.svmtrain(y, X, '-c 10 -g 0.8 -q');
check(isequal(fieldnames(model)', {'Parameters', 'nr_class', 'totalSV', 'rho', 'Label', 'sv_indices', ...
      'ProbA', 'ProbB', 'nSV', 'sv_coef', 'SVs'}), 'the model struct has LIBSVM''s fields in order');
check(isequal(model.Parameters', [3 2 3 0.8 0]) && model.nr_class == 2 && issparse(model.SVs) && ...
      model.totalSV == numel(model.sv_coef) && isempty(model.Label), 'LIBSVM''s field values');
pairs = fogdrift.svmtrain(y, X, '-c 10 -g 0.8 -q --solver pairs');
pp = fogdrift.svmpredict(yt, Xt, pairs, '-q');
pl = fogdrift.svmpredict(yt, Xt, model, '-q');
check(max(abs(pp - pl)) < 1e-2 * std(yt), '--solver pairs: the same optimum to the tolerance');
mse = fogdrift.svmtrain(y, X, '-v 5 -c 10 -g 0.8 -q');
check(isscalar(mse) && mse > 0 && mse < var(y), '-v 5 returns the cross-validated MSE');
check(mse == fogdrift.svmtrain(y, X, '-v 5 -c 10 -g 0.8 -q'), '-v is the same every run');
% Features beyond the model's count as zero (LIBSVM's rule).
two = fogdrift.svmtrain(y, X(:, 1:2), '-c 10 -g 0.8 -q');
p3 = fogdrift.svmpredict(yt, [Xt(:, 1:2), zeros(50, 1)], two, '-q');
p2 = fogdrift.svmpredict(yt, Xt(:, 1:2), two, '-q');
check(isequal(p2, p3), 'a zero feature the model never saw changes nothing');
[yl, Xl] = fogdrift.libsvmread('ref_train.txt');
check(isequal(yl, y) && issparse(Xl) && isequal(full(Xl), X), 'libsvmread reads what was written');

expect_error(@() fogdrift.svmtrain(y, X, '-s 0'), 'fogdrift:badOption', 'svm_type 0 (C-SVC) is not supported', 'C-SVC refused');
expect_error(@() fogdrift.svmtrain(y, X, '-t 1'), 'fogdrift:badOption', 'kernel_type 1 (polynomial)', 'polynomial refused');
expect_error(@() fogdrift.svmtrain(y, X, '-b 1'), 'fogdrift:badOption', 'probability estimates', '-b 1 refused');
expect_error(@() fogdrift.svmtrain(y, X, '-c ten'), 'fogdrift:badOption', 'option -c: ''ten'' is not a finite number', 'a word for C');
expect_error(@() fogdrift.svmtrain(y, X, '-c 0'), 'fogdrift:badOption', 'option -c', 'C = 0');
expect_error(@() fogdrift.svmtrain(y(1:10), X), 'fogdrift:badInput', 'has 240 rows and the label vector 10', 'rows differ');
bad = X; bad(7, 2) = NaN;
expect_error(@() fogdrift.svmtrain(y, bad), 'fogdrift:badInput', 'instance matrix:7:2: is not a finite number', 'a NaN named by row and column');
expect_error(@() fogdrift.svmtrain(y, single(X)), 'fogdrift:badInput', 'must be a real double matrix', 'single refused');
expect_error(@() fogdrift.svmtrain(y, X, 3), 'fogdrift:badInput', 'libsvm_options: must be text', 'options not text');
expect_error(@() fogdrift.svmpredict(yt, Xt, struct('a', 1)), 'fogdrift:badInput', 'has no field Parameters', 'not a model');
c = model; c.Parameters(1) = 0;
expect_error(@() fogdrift.svmpredict(yt, Xt, c), 'fogdrift:badOption', 'C-SVC', 'a C-SVC model refused');
c = model; c.sv_coef(2) = NaN;
expect_error(@() fogdrift.svmpredict(yt, Xt, c), 'fogdrift:badInput', 'not finite', 'an edited coefficient refused');
c = model; c.Parameters(4) = 0;
expect_error(@() fogdrift.svmpredict(yt, Xt, c), 'fogdrift:badInput', 'gamma is 0', 'an RBF model without gamma refused');
c = model; c.Parameters(1) = 3.5;
expect_error(@() fogdrift.svmpredict(yt, Xt, c), 'fogdrift:badInput', 'not an SVM or kernel type', 'a type that is no type refused');
c = model; c.SVs(1, 1) = Inf;
expect_error(@() fogdrift.svmpredict(yt, Xt, c), 'fogdrift:badInput', 'model.SVs: holds a value that is not finite', 'an infinite support vector refused');
expect_error(@() fogdrift.svmpredict(yt, Xt, model, '-b 1'), 'fogdrift:badOption', 'probability', '-b 1 refused in predict');
printf('all passed\n');
