function expect_error(f, id, text, what)
% EXPECT_ERROR  Passes when f() raises an error of identifier ID whose message holds TEXT.
  try
    f();
  catch e
    check(strcmp(e.identifier, id) && ~isempty(strfind(e.message, text)), ...
          sprintf('%s: %s', what, e.message));
    return;
  end
  error('test:failed', 'failed: %s raised nothing', what);
end
