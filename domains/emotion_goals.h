// The paper's goal generation (its Section 6.1): the goal a senior's
// emotion calls for — terrified -> (soothed s), sad -> (cheerful s), bored ->
// (entertained s) — read from the observed state. The monitor re-invokes it
// on every failure, so that a changed emotion changes the goal.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pddl_parser/ast.h"
#include "repair/world_state.h"

namespace alplan::domains {

// The paper's table: the goal predicate an emotion calls for ("terrified"
// -> "soothed", "sad" -> "cheerful", "bored" -> "entertained"), or nothing.
std::optional<std::string_view> goal_for_emotion(std::string_view emotion);

// (predicate senior), as the domain's one-senior predicates are written.
pddl::Atom senior_atom(const std::string& predicate, const std::string& senior);
pddl::Condition senior_condition(const std::string& predicate, const std::string& senior);

// The goal and the reason for it ("senior1 is sad"), or nothing.
using GoalGenerator =
    std::function<std::optional<std::pair<pddl::Condition, std::string>>(const repair::WorldState&)>;

// One senior: the goal is the atom, as the paper's problems write it.
GoalGenerator emotion_goal_generator(const std::string& senior);

// Several seniors (generated homes): the goal is the conjunction, as
// `gen home` writes it, of what each senior's emotion calls for; a senior
// already comforted keeps the goal that holds, so it is not dropped.
GoalGenerator emotion_goal_generator(const std::vector<std::string>& seniors);

}  // namespace alplan::domains
