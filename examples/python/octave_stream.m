% Octave drives cic through its JSON-lines stream (`cic eval`), as the thesis's
% MATLAB integration did: a (1+1)-ES on R1's gait, one line out, one line back.
%
%   octave-cli examples/python/octave_stream.m
%
% Environment: CIC (the cic binary, default "cic"), CIC_SETTINGS (default
% r1_gait.xml, found like cic --settings), CIC_QUICK=1 for 3 s walks (tests).
1;

function line = read_line(from_cic)
  % Octave's popen2 pipes do not block: wait for a whole line.
  line = fgetl(from_cic);
  while ~ischar(line)
    fclear(from_cic);
    pause(0.01);
    line = fgetl(from_cic);
  end
end

function r = score(to_cic, from_cic, x)
  fputs(to_cic, [jsonencode(struct("genotype", x(:)')) "\n"]);
  fflush(to_cic);
  r = jsondecode(read_line(from_cic));
  if isfield(r, "error")
    error("cic: %s", r.error);
  end
end

cic = getenv("CIC");
if isempty(cic), cic = "cic"; end
settings = getenv("CIC_SETTINGS");
if isempty(settings), settings = "r1_gait.xml"; end
args = {"eval", "--settings", settings};
if strcmp(getenv("CIC_QUICK"), "1")
  args = [args, {"--set", "Simulator.sample_to=3", "--set", "Simulator.delayed_start=0.5"}];
end

[status, text] = system(sprintf('"%s" eval --settings "%s" --info', cic, settings));
info = jsondecode(text);
[to_cic, from_cic, pid] = popen2(cic, args);

rand("seed", 1);
x = 0.5 * ones(info.dimension, 1);
best = score(to_cic, from_cic, x).fitness;
for k = 1:20
  y = min(max(x + 0.1 * randn(info.dimension, 1), 0), 1);
  r = score(to_cic, from_cic, y);
  if r.fitness > best
    x = y;
    best = r.fitness;
  end
  printf("step %2d  best %.4f\n", k, best);
end
fclose(to_cic);
fclose(from_cic);
waitpid(pid);
printf("best fitness %.6f\n", best);
