function varargout = call(varargin)
%CALL  Calls the MEX gateway creepwork_mex (the other functions of the package do).
%   Its errors are raised again without the "creepwork_mex: " Octave puts
%   before a MEX's message, keeping their identifier (creepwork:<status>).
  try
    [varargout{1:nargout}] = creepwork_mex(varargin{:});
  catch err
    error(err.identifier, '%s', regexprep(err.message, '^creepwork_mex: ', ''));
  end
end
