% EXPECT_ERROR(F, ID, PATTERN): calling F raises the error ID, its message
% matching the regular expression PATTERN (shared by the tests of errors).
function expect_error(f, id, pattern)
  try
    f();
  catch err
    assert(strcmp(err.identifier, id), sprintf('identifier %s, expected %s (%s)', ...
                                               err.identifier, id, err.message));
    assert(~isempty(regexp(err.message, pattern, 'once')), ...
           sprintf('message "%s" does not match %s', err.message, pattern));
    return;
  end
  error('test:noError', 'no error, expected %s', id);
end
