#!/usr/bin/python3
"""Mutation runs of `alplan plan` on the continuous-change domains: each run takes a domain and problem of
domains/continuous, inserts #t forms, operators, numbers, or cuts text at random places, and plans with a 2 s
limit. Any exit by a signal, or exit 70 (a plan the validator rejects), is kept in OUT/crash-N with the inputs.
The grounding, linearisation and LP paths are what it reaches that the parser fuzzer (fuzz_parser.sh) does not.
    benchmarks/mutate_continuous.py [SECONDS] [SEED] [ALPLAN] [OUT]
"""
import glob, os, random, subprocess, sys, time

here = os.path.dirname(os.path.abspath(__file__))
seconds = float(sys.argv[1]) if len(sys.argv) > 1 else 120
random.seed(int(sys.argv[2]) if len(sys.argv) > 2 else 1)
alplan = sys.argv[3] if len(sys.argv) > 3 else os.path.join(here, '..', 'build', 'cli', 'alplan')
out = sys.argv[4] if len(sys.argv) > 4 else '/tmp/mutate-continuous'
os.makedirs(out, exist_ok=True)
domains = sorted(glob.glob(os.path.join(here, '..', 'domains', 'continuous', '*', 'domain.pddl')))
pieces = ['(', ')', '#t', '(* #t 2)', '(* #t (* #t 2))', '(* #t ?duration)', '?duration', '(increase', '(decrease',
          '(assign', '-1', '0', '1e308', '(/ 1 0)', 'over all', 'at start', 'at end', '(>=', '(<=', '(=', '(when',
          '(forall', '(and', 'nan']


def mutate(text):
    i = random.randrange(len(text))
    op = random.random()
    if op < 0.4:
        return text[:i] + random.choice(pieces) + text[i:]
    if op < 0.7:
        return text[:i] + text[min(len(text), i + random.randint(1, 20)):]
    return text[:i] + str(random.choice([0, -5, 3.5, 1e9, -1e-9])) + text[i:]


end = time.time() + seconds
runs = findings = 0
while time.time() < end:
    domain_path = random.choice(domains)
    problem_path = random.choice(sorted(glob.glob(os.path.join(os.path.dirname(domain_path), 'p0[12].pddl'))))
    texts = [open(domain_path).read(), open(problem_path).read()]
    for _ in range(random.randint(1, 4)):
        k = 0 if random.random() < 0.8 else 1
        texts[k] = mutate(texts[k])
    paths = [os.path.join(out, 'domain.pddl'), os.path.join(out, 'problem.pddl')]
    for path, text in zip(paths, texts):
        open(path, 'w').write(text)
    r = subprocess.run([alplan, 'plan', '--time-limit', '2'] + paths, capture_output=True, timeout=60)
    runs += 1
    if r.returncode < 0 or r.returncode == 70:
        findings += 1
        keep = os.path.join(out, f'crash-{findings}')
        os.makedirs(keep, exist_ok=True)
        for path, text in zip(paths, texts):
            open(os.path.join(keep, os.path.basename(path)), 'w').write(text)
        open(os.path.join(keep, 'output.txt'), 'wb').write(r.stdout + r.stderr + f'\nexit {r.returncode}\n'.encode())
print(f'{runs} runs, {findings} crashes or internal errors (kept in {out})')
sys.exit(1 if findings else 0)
