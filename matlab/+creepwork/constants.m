function c = constants()
%CONSTANTS  Every constant and status code of creepwork.h, by its C name.
%   C = creepwork.constants(); C.CW_MODEL_EXACT, C.CW_ERR_INVALID_INPUT, ...
  persistent cached
  if isempty(cached)
    cached = creepwork.call('constants');
  end
  c = cached;
end
