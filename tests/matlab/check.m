function check(cond, what)
% CHECK  Fails the Octave test with WHAT unless COND; prints "ok  WHAT" otherwise.
  if ~cond, error('test:failed', 'failed: %s', what); end
  printf('ok  %s\n', what);
end
