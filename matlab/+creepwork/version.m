function v = version()
%VERSION  The version of the loaded creepwork library, e.g. '1.1.0'.
  v = creepwork.call('version');
end
