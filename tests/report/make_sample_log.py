#!/usr/bin/python3
"""Writes a sample `alplan home` event log (JSON Lines) for the report tests.

A made-up run in the issue-16 format, until `alplan home` writes real ones:
three seniors, two robots; plan 1 is superseded by a merge (plan 2) while
robot1 is on its way, a missing glass fails plan 2 and is repaired by
substitution (plan 3), senior2 moving defeats a replan and her window is
missed, senior1 is comforted in time and senior3 late. Deterministic.

Usage: make_sample_log.py OUT [--damage]
  --damage  adds a line that is not JSON and truncates the last line, as a
            crashed run leaves its log.
"""
import json
import math
import random
import sys

HOME = {
    "name": "sample home <3 seniors>",
    "rooms": [
        {"name": "bedroom1", "x": 1.0, "y": 5.0}, {"name": "bedroom2", "x": 1.0, "y": 1.0},
        {"name": "corridor1", "x": 4.0, "y": 3.0}, {"name": "living_room1", "x": 7.0, "y": 5.5},
        {"name": "corridor2", "x": 8.0, "y": 3.0}, {"name": "kitchen1", "x": 11.0, "y": 1.0},
        {"name": "dinning_room1", "x": 11.0, "y": 5.0},
    ],
    "connections": [
        ["bedroom1", "corridor1"], ["bedroom2", "corridor1"], ["corridor1", "living_room1"],
        ["corridor1", "corridor2"], ["corridor2", "kitchen1"], ["corridor2", "dinning_room1"],
        ["living_room1", "dinning_room1"],
    ],
    "seniors": [{"name": "senior1", "room": "bedroom1"}, {"name": "senior2", "room": "living_room1"},
                {"name": "senior3", "room": "bedroom2"}],
    "robots": [{"name": "robot1", "room": "corridor1"}, {"name": "robot2", "room": "corridor2"}],
    "objects": [{"name": "glass_id05", "type": "glass", "room": "kitchen1"},
                {"name": "mug_id02", "type": "mug", "room": "kitchen1"},
                {"name": "radio_id01", "type": "radio", "room": "living_room1"}],
}
SETTINGS = {"seed": 7, "strategy": "substitute", "observe": "iot", "until": 200, "seniors": 3, "robots": 2}

# (senior, stressed from, stressed until, emotion while stressed)
MOODS = [("senior1", 10, 75, "sad"), ("senior2", 30, 150, "terrified"), ("senior3", 100, 175, "angry")]


def step(start, duration, action):
    return {"start": start, "duration": duration, "action": action, "robot": action.split()[1]}


PLAN1 = [step(12.5, 10, "(move robot1 corridor1 corridor2)"), step(22.5, 8, "(move robot1 corridor2 kitchen1)"),
         step(30.5, 5, "(pick robot1 glass_id05 kitchen1)"), step(35.5, 8, "(move robot1 kitchen1 corridor2)"),
         step(43.5, 10, "(move robot1 corridor2 corridor1)"), step(53.5, 6, "(move robot1 corridor1 bedroom1)"),
         step(59.5, 10, "(give robot1 glass_id05 senior1)")]
PLAN2 = PLAN1[2:] + [step(25.5, 7, "(move robot2 corridor2 dinning_room1)"),
                     step(32.5, 9, "(move robot2 dinning_room1 living_room1)"),
                     step(41.5, 20, "(play_music robot2 radio_id01 senior2)")]
PLAN3 = [step(32, 5, "(pick robot1 mug_id02 kitchen1)"), step(37, 8, "(move robot1 kitchen1 corridor2)"),
         step(45, 10, "(move robot1 corridor2 corridor1)"), step(55, 6, "(move robot1 corridor1 bedroom1)"),
         step(61, 10, "(give robot1 mug_id02 senior1)")] + PLAN2[-2:]
PLAN4 = [step(106, 9, "(move robot2 living_room1 corridor1)"), step(115, 6, "(move robot2 corridor1 bedroom2)"),
         step(121, 15, "(talk robot2 senior3)")]


def ipc(steps):
    return "\n".join(f"{s['start']:.3f}: {s['action']} [{s['duration']:.3f}]" for s in steps)


def plan(t, plan_id, reason, supersedes, steps):
    return {"type": "plan", "time": t, "plan_id": plan_id, "reason": reason, "supersedes": supersedes,
            "plan": ipc(steps), "steps": steps, "planning_seconds": 0.04 * len(steps)}


def run_actions(steps, plan_id, until=math.inf, fail_at=None):
    """action_start/action_end of the steps that start before `until`."""
    events = []
    for s in steps:
        if s["start"] >= until:
            continue
        robot = s["robot"]
        events.append({"type": "action_start", "time": s["start"], "robot": robot, "action": s["action"],
                       "plan_id": plan_id})
        if fail_at is None or s["action"] != fail_at:
            events.append({"type": "action_end", "time": s["start"] + s["duration"], "robot": robot,
                           "action": s["action"], "plan_id": plan_id})
    return events


def moods():
    rng = random.Random(7)
    events = []
    for senior, since, until, emotion in MOODS:
        for t in range(0, 201, 5):
            stressed = since <= t < until
            score = round((0.75 if stressed else 0.2) + rng.uniform(-0.12, 0.12), 3)
            events.append({"type": "stress", "time": t, "senior": senior, "stressed": stressed, "score": score})
            if t % 10 == 0:
                events.append({"type": "emotion", "time": t + 1, "senior": senior,
                               "emotion": emotion if stressed else "neutral",
                               "score": round(rng.uniform(0.55, 0.95), 3), "look": t // 10})
    return events


def story():
    e = [
        {"type": "goal", "time": 12, "senior": "senior1", "goal": "(cheerful senior1)", "emotion": "sad",
         "motivation": "senior1 is stressed and sad", "decided_by": "goal generator", "window_end": 132},
        plan(12.5, 1, "initial", None, PLAN1),
        {"type": "goal", "time": 25, "senior": "senior2", "goal": "(calm senior2)", "emotion": "terrified",
         "motivation": "senior2 is stressed and terrified", "decided_by": "goal generator", "window_end": 100},
        plan(25.5, 2, "merge", 1, PLAN2),
        {"type": "observation", "time": 30.5, "robot": "robot1", "what": "sighting",
         "detail": "kitchen1: mug_id02 seen; glass_id05 not seen"},
        {"type": "failure", "time": 31, "robot": "robot1", "action": "(pick robot1 glass_id05 kitchen1)",
         "condition": "(at glass_id05 kitchen1)", "kind": "object_missing", "foreseen": False},
        {"type": "repair", "time": 31.5, "strategy": "substitute", "repaired": True, "seconds": 0.21, "plan_id": 3,
         "how": "a mug holds a drink as a glass does"},
        {"type": "explanation", "time": 31.5, "senior": "senior1", "why": "senior1 is sad and needs a drink",
         "what": "glass_id05 was not in kitchen1", "how": "use mug_id02 <a mug> & carry on"},
        plan(31.5, 3, "repair", 2, PLAN3),
        {"type": "failure", "time": 52, "robot": "robot2", "action": "(play_music robot2 radio_id01 senior2)",
         "condition": "(at senior2 living_room1)", "kind": "senior_moved", "foreseen": True,
         "extra_field": "unknown fields are allowed"},
        {"type": "repair", "time": 53, "strategy": "replan", "repaired": False, "seconds": 1.2, "plan_id": None,
         "how": "no plan reaches senior2 within her window"},
        {"type": "explanation", "time": 53, "senior": "senior2", "why": "senior2 is terrified",
         "what": "senior2 left living_room1", "how": "could not be repaired in time"},
        {"type": "comforted", "time": 71, "senior": "senior1", "goal": "(cheerful senior1)", "window_end": 132,
         "within_window": True},
        {"type": "window_missed", "time": 100, "senior": "senior2", "goal": "(calm senior2)", "window_end": 100},
        {"type": "goal", "time": 105, "senior": "senior3", "goal": "(calm senior3)", "emotion": "angry",
         "motivation": "senior3 is stressed and angry", "decided_by": "goal generator", "window_end": 130},
        plan(106, 4, "merge", 3, PLAN4),
        {"type": "comforted", "time": 136, "senior": "senior3", "goal": "(calm senior3)", "window_end": 130,
         "within_window": False},
        {"type": "explanation", "time": 136, "why": "senior3 was angry", "what": "comforted 6 s late",
         "how": "robot2 came from living_room1"},
    ]
    e += run_actions(PLAN1, 1, until=25.5)
    e += run_actions(PLAN2, 2, until=31.5, fail_at="(pick robot1 glass_id05 kitchen1)")
    e += run_actions(PLAN3, 3, fail_at="(play_music robot2 radio_id01 senior2)")
    e += run_actions(PLAN4, 4)
    return e


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    events = sorted(moods() + story(), key=lambda ev: ev["time"])  # stable: story order kept at equal times
    lines = [json.dumps({"type": "observation", "time": 0, "what": "home", "home": HOME, "settings": SETTINGS})]
    lines += [json.dumps(ev) for ev in events]
    if "--damage" in sys.argv[2:]:
        lines.insert(17, '{"type": "stress", "time": 3, "senior": ')
        lines[-1] = lines[-1][: len(lines[-1]) // 2]
    with open(sys.argv[1], "w", encoding="utf-8") as out:
        out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
