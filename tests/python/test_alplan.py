"""The Python module as a researcher uses it (issue 17): parse, ground, plan,
validate, errors that name the place, and planning that lets other Python
threads run. Needs ALPLAN_SHARED_DIR (the shared benchmarks) and the module
on PYTHONPATH (CTest sets both)."""
import os
import threading

import pytest

import alplan

SHARED = os.environ.get("ALPLAN_SHARED_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared"))
IPC = os.path.join(SHARED, "benchmarks", "ipc")
MATCH = os.path.join(IPC, "ipc-2014", "match-cellar-temporal-satisficing")
STORAGE = os.path.join(IPC, "ipc-2011", "storage-temporal-satisficing")

DOMAIN = """(define (domain hand) (:requirements :typing :durative-actions)
  (:types ball room)
  (:predicates (at ?b - ball ?r - room) (free))
  (:durative-action carry :parameters (?b - ball ?from ?to - room)
    :duration (= ?duration 2)
    :condition (and (at start (at ?b ?from)) (at start (free)))
    :effect (and (at start (not (at ?b ?from))) (at start (not (free)))
                 (at end (at ?b ?to)) (at end (free)))))"""
PROBLEM = """(define (problem one) (:domain hand)
  (:objects b1 b2 - ball r1 r2 - room)
  (:init (at b1 r1) (at b2 r1) (free))
  (:goal (and (at b1 r2) (at b2 r2))))"""


def test_parse_strings_gives_immutable_summaries():
    domain = alplan.parse_domain_string(DOMAIN)
    assert domain.name == "hand"
    assert domain.actions == ["carry"]
    assert set(domain.types) == {"ball", "room"}
    problem = alplan.parse_problem_string(PROBLEM, domain)
    assert problem.objects == ["b1", "b2", "r1", "r2"]
    assert "(at b1 r1)" in problem.init
    assert problem.goal == "(and (at b1 r2) (at b2 r2))"
    assert "(:durative-action carry" in domain.to_pddl()


def test_a_pddl_error_names_file_line_and_column():
    with pytest.raises(alplan.PddlError) as caught:
        alplan.parse_domain_string("(define (domain d)\n  (:predicates (p ?x - )))", "broken.pddl")
    error = caught.value
    assert isinstance(error, ValueError)
    assert (error.file, error.line, error.column) == ("broken.pddl", 2, 24)
    assert "expected a type name" in str(error)
    assert error.diagnostics and error.diagnostics[0].startswith("broken.pddl:2:24: error:")


def test_a_problem_is_checked_against_its_domain():
    domain = alplan.parse_domain_string(DOMAIN)
    with pytest.raises(alplan.PddlError) as caught:
        alplan.parse_problem_string(PROBLEM.replace("(free)", "(lost b1)"), domain, "p.pddl")
    assert caught.value.file == "p.pddl"
    assert caught.value.line == 3


def test_a_missing_file_is_an_os_error():
    with pytest.raises(OSError):
        alplan.parse_domain("/nonexistent/domain.pddl")


def test_warnings_are_kept():
    text = DOMAIN.replace("?b - ball ?r - room", "?b -ball ?r - room")
    domain = alplan.parse_domain_string(text, "glued.pddl")
    assert any("'-' is written against the name" in w for w in domain.warnings)


def test_plan_from_strings_and_validate():
    domain = alplan.parse_domain_string(DOMAIN)
    problem = alplan.parse_problem_string(PROBLEM, domain)
    result = alplan.plan(domain, problem, time_limit=10)
    assert result.status == "solved"
    assert [s.action for s in result.steps] == ["carry", "carry"]
    first = result.steps[0]
    assert first.time == 0.0 and first.duration == 2.0
    assert first.name.startswith("(carry b")
    assert result.makespan == pytest.approx(4.001)  # one hand: the second carry waits
    assert alplan.validate(domain, problem, result).valid


def test_search_configurations_by_expression_and_alias():
    domain = alplan.parse_domain_string(DOMAIN)
    problem = alplan.parse_problem_string(PROBLEM, domain)
    for options in ({"search": "complete(wastar(blind, w=1))"}, {"alias": "complete"},
                    {"search": "then(ehc(trpg, expansions=10), portfolio(gbfs(trpg), wastar(trpg, w=2)))"}):
        result = alplan.plan(domain, problem, time_limit=10, **options)
        assert result.status == "solved", options
        assert alplan.validate(domain, problem, result).valid
    with pytest.raises(ValueError, match="unknown heuristic 'ff'"):
        alplan.plan(domain, problem, time_limit=10, search="gbfs(ff)")


def test_plan_a_shared_benchmark_problem_from_files():
    result = alplan.plan(os.path.join(MATCH, "domain.pddl"), os.path.join(MATCH, "instances", "instance-1.pddl"),
                         time_limit=30)
    assert result.status == "solved"
    assert result.statistics["expanded"] > 0
    assert result.makespan == max(s.time + (s.duration or 0.0) for s in result.steps)
    checked = alplan.validate(os.path.join(MATCH, "domain.pddl"), os.path.join(MATCH, "instances", "instance-1.pddl"),
                              result.text)
    assert checked.valid and checked.violation is None


def test_anytime_gives_improving_plans():
    result = alplan.plan(os.path.join(MATCH, "domain.pddl"), os.path.join(MATCH, "instances", "instance-1.pddl"),
                         time_limit=5, anytime=True, anytime_expansions=2000)
    assert result.plans
    values = [p.metric if p.metric is not None else p.makespan for p in result.plans]
    assert values == sorted(values, reverse=True)


def test_options_are_checked():
    with pytest.raises(TypeError, match="unexpected keyword argument 'speed'"):
        alplan.plan(os.path.join(MATCH, "domain.pddl"), os.path.join(MATCH, "instances", "instance-1.pddl"), speed=2)
    with pytest.raises(ValueError, match="unknown engine 'dfs'"):
        alplan.plan(os.path.join(MATCH, "domain.pddl"), os.path.join(MATCH, "instances", "instance-1.pddl"),
                    search="dfs")
    with pytest.raises(ValueError, match="order must be"):
        alplan.plan(os.path.join(MATCH, "domain.pddl"), os.path.join(MATCH, "instances", "instance-1.pddl"),
                    order="cost")


def test_an_invalid_plan_gives_a_typed_violation():
    domain = alplan.parse_domain_string(DOMAIN)
    problem = alplan.parse_problem_string(PROBLEM, domain)
    overlapping = "0.000: (carry b1 r1 r2) [2.000]\n0.000: (carry b2 r1 r2) [2.000]\n"
    result = alplan.validate(domain, problem, overlapping)
    assert not result.valid
    assert result.violation.kind in ("unsatisfied_precondition", "mutex_violation")
    assert result.violation.message


def test_ground_reports_sizes():
    domain = alplan.parse_domain_string(DOMAIN)
    task = alplan.ground(domain, alplan.parse_problem_string(PROBLEM, domain))
    # two balls, from either room (both reachable) to either room
    assert task.actions == len(task.action_names()) == 8
    assert "(carry b1 r1 r2)" in task.action_names()
    assert task.facts > 0


def test_planning_releases_the_gil():
    # While one thread searches a problem it cannot solve within its second,
    # this thread keeps counting: with the GIL held it could not.
    done = threading.Event()
    outcome = {}

    def search():
        outcome["result"] = alplan.plan(os.path.join(STORAGE, "domain.pddl"),
                                        os.path.join(STORAGE, "instances", "instance-5.pddl"), time_limit=1.0)
        done.set()

    worker = threading.Thread(target=search)
    worker.start()
    counted = 0
    while not done.is_set():
        counted += 1
    worker.join()
    assert outcome["result"].status in ("limit_reached", "solved")
    assert counted > 10000


def test_two_threads_plan_at_once():
    results = [None, None]

    def search(i):
        results[i] = alplan.plan(os.path.join(MATCH, "domain.pddl"),
                                 os.path.join(MATCH, "instances", "instance-%d.pddl" % (i + 1)), time_limit=30)

    threads = [threading.Thread(target=search, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert [r.status for r in results] == ["solved", "solved"]


def test_the_gantt_example_draws_a_plan(tmp_path):
    import runpy
    import sys

    out = tmp_path / "plan.png"
    argv = sys.argv
    sys.argv = ["gantt.py", "--out", str(out)]
    try:
        runpy.run_path(os.path.join(os.path.dirname(__file__), "..", "..", "python", "examples", "gantt.py"),
                       run_name="__main__")
    finally:
        sys.argv = argv
    assert out.stat().st_size > 5000


class HandWorld:
    """The one-hand domain's world, written in Python: the robot's carries do
    what the domain says, and at time 1 somebody else carries the ball still
    waiting in r1 to r2."""

    def __init__(self):
        self.atoms = {"(at b1 r1)", "(at b2 r1)", "(free)"}
        self.now = 0.0
        self.calls = []

    def advance(self, t):
        if self.now < 1.0 <= t:
            for ball in ("b1", "b2"):
                if "(at %s r1)" % ball in self.atoms:
                    self.atoms.discard("(at %s r1)" % ball)
                    self.atoms.add("(at %s r2)" % ball)
                    self.moved = ball
        self.now = t

    def observe(self):
        return {"atoms": sorted(self.atoms), "values": {}, "time": self.now}

    def start_action(self, name, t, duration):
        self.calls.append(("start", name, t))
        _, ball, src, _dst = name.strip("()").split()
        self.atoms -= {"(at %s %s)" % (ball, src), "(free)"}

    def end_action(self, name, t):
        self.calls.append(("end", name, t))
        _, ball, _src, dst = name.strip("()").split()
        self.atoms |= {"(at %s %s)" % (ball, dst), "(free)"}
        return True


@pytest.mark.parametrize("strategy", ["replan", "adapt"])
def test_the_monitor_runs_against_a_world_written_in_python(strategy):
    assert "replan" in alplan.strategies()
    domain = alplan.parse_domain_string(DOMAIN)
    problem = alplan.parse_problem_string(PROBLEM, domain)
    world = HandWorld()
    report = alplan.execute(domain, problem, world, strategy=strategy)
    assert report["goal_reached"], report["outcome"]
    assert report["repairs"], "a ball moved by somebody else: the plan's second carry must fail"
    repair = report["repairs"][0]
    assert repair["condition"] == "(at %s r1)" % world.moved
    assert repair["explanation"]["repaired"]
    assert world.calls[0][0] == "start"
    assert "(at b1 r2)" in world.atoms and "(at b2 r2)" in world.atoms


def test_an_unknown_strategy_is_a_value_error():
    domain = alplan.parse_domain_string(DOMAIN)
    with pytest.raises(ValueError, match="unknown repair strategy"):
        alplan.execute(domain, alplan.parse_problem_string(PROBLEM, domain), HandWorld(), strategy="pray")


def test_version_is_the_projects():
    # One place: CMakeLists.txt's project(), which `alplan --version` prints too.
    import re
    root = os.path.join(os.path.dirname(__file__), "..", "..")
    with open(os.path.join(root, "CMakeLists.txt"), encoding="utf-8") as cmake:
        version = re.search(r"project\(alplan VERSION ([0-9.]+)", cmake.read()).group(1)
    assert alplan.__version__ == version
