// The abstract syntax tree of PDDL 2.2 domains and problems (with the PDDL 3
// constraints and preferences the IPC files may carry).
//
// Contract: the parser produces these nodes once and hands them out as
// `std::shared_ptr<const Domain>` / `std::shared_ptr<const Problem>`; nothing
// downstream mutates them (grounding builds its own data, as the Fast Downward
// translator does). Every name is lower-case, since PDDL is case-insensitive;
// variables keep their leading '?'. Every node carries the position where it
// began. Node equality compares content and ignores positions.
//
// Reference: Edelkamp & Hoffmann, "PDDL2.2: The Language for the Classical
// Part of the 4th International Planning Competition" (2004); Fox & Long,
// "PDDL2.1" (JAIR 2003) for durative actions; Gerevini & Long, "PDDL3" (2005).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "pddl_parser/source_location.h"

namespace alplan::pddl {

// A type expression: one name, several for `(either a b ...)`, none for the
// implicit `object`.
using TypeNames = std::vector<std::string>;

// A variable (`?x`) or an object/constant name with its declared type.
struct TypedName {
  std::string name;
  TypeNames types;
  SourceLocation location;
  bool operator==(const TypedName&) const = default;
};

struct Requirement {
  std::string name;  // with the leading ':'
  SourceLocation location;
  bool operator==(const Requirement&) const = default;
};

// `a b - c` declares a and b with parent c; `a - (either b c)` gives a two
// parents (multiple inheritance through either).
struct TypeDeclaration {
  std::string name;
  TypeNames parents;
  SourceLocation location;
  bool operator==(const TypeDeclaration&) const = default;
};

// An argument of an atom or function term.
struct Term {
  enum class Kind : unsigned char { Name, Variable };
  Kind kind = Kind::Name;
  std::string name;
  SourceLocation location;
  bool is_variable() const { return kind == Kind::Variable; }
  bool operator==(const Term&) const = default;
};

// `(name arg...)`: a predicate atom or, in numeric contexts, a function term.
struct Atom {
  std::string name;
  std::vector<Term> args;
  SourceLocation location;
  bool operator==(const Atom&) const = default;
};
using FunctionTerm = Atom;

struct NumericExpression {
  enum class Kind : unsigned char {
    Number,
    Function,        // (f a b)
    Add,             // (+ e e ...)
    Subtract,        // (- e e)
    Multiply,        // (* e e ...)
    Divide,          // (/ e e)
    Negate,          // (- e)
    Duration,        // ?duration
    TotalTime,       // (total-time), in metrics
    ContinuousTime,  // #t, in continuous effects
    IsViolated,      // (is-violated pref), PDDL 3 metrics
  };
  Kind kind = Kind::Number;
  double value = 0.0;
  FunctionTerm function;  // Function; for IsViolated the preference name
  std::vector<NumericExpression> operands;
  SourceLocation location;
  bool operator==(const NumericExpression&) const = default;
};

enum class Comparison : unsigned char { Less, LessEqual, Equal, GreaterEqual, Greater };
enum class TimeSpecifier : unsigned char { AtStart, AtEnd, OverAll };

// A goal description: preconditions, durative conditions, goals, derived
// predicate bodies and PDDL 3 constraints share this one node type.
struct Condition {
  enum class Kind : unsigned char {
    And,
    Or,
    Not,
    Imply,
    Exists,
    Forall,
    Atom,
    Equality,    // (= t1 t2) between objects
    Comparison,  // (op e1 e2) between numeric expressions
    Timed,       // (at start C), (at end C), (over all C)
    Preference,  // (preference [name] C)
    // PDDL 3 trajectory constraints.
    Always,
    Sometime,
    Within,        // (within n C)
    AtMostOnce,
    SometimeAfter,   // (sometime-after C1 C2)
    SometimeBefore,  // (sometime-before C1 C2)
    AlwaysWithin,    // (always-within n C1 C2)
    HoldDuring,      // (hold-during n1 n2 C)
    HoldAfter,       // (hold-after n C)
  };
  Kind kind = Kind::And;
  TimeSpecifier time = TimeSpecifier::AtStart;  // Timed
  Comparison comparison = Comparison::Equal;    // Comparison
  Atom atom;                                    // Atom; Equality holds its two terms in atom.args
  std::vector<TypedName> variables;             // Exists, Forall
  std::vector<Condition> children;
  std::vector<NumericExpression> expressions;   // Comparison: left, right
  std::vector<double> numbers;                  // Within, AlwaysWithin, HoldDuring, HoldAfter
  std::string preference_name;                  // Preference (may be empty)
  SourceLocation location;
  bool operator==(const Condition&) const = default;
};

enum class AssignOperator : unsigned char { Assign, Increase, Decrease, ScaleUp, ScaleDown };

struct Effect {
  enum class Kind : unsigned char {
    And,
    Forall,   // (forall (vars) E): children[0]
    When,     // (when C E): condition, children[0]
    Add,      // atom
    Delete,   // (not atom)
    Numeric,  // (op (f args) value)
    Timed,    // (at start E), (at end E): children[0]
  };
  Kind kind = Kind::And;
  TimeSpecifier time = TimeSpecifier::AtStart;   // Timed
  AssignOperator assign = AssignOperator::Assign;  // Numeric
  Atom atom;                                       // Add, Delete; Numeric: the function term
  std::vector<TypedName> variables;                // Forall
  std::optional<Condition> condition;              // When
  std::optional<NumericExpression> value;          // Numeric
  std::vector<Effect> children;
  SourceLocation location;
  bool operator==(const Effect&) const = default;
};

// One conjunct of `:duration`: (op ?duration value), optionally timed as in
// PDDL 2.1's `(at end (<= ?duration e))`.
struct DurationConstraint {
  Comparison comparison = Comparison::Equal;
  NumericExpression value;
  std::optional<TimeSpecifier> time;
  SourceLocation location;
  bool operator==(const DurationConstraint&) const = default;
};

struct PredicateDeclaration {
  std::string name;
  std::vector<TypedName> parameters;
  SourceLocation location;
  bool operator==(const PredicateDeclaration&) const = default;
};

struct FunctionDeclaration {
  std::string name;
  std::vector<TypedName> parameters;
  std::string value_type = "number";  // `- number` (the default), or an object type
  SourceLocation location;
  bool operator==(const FunctionDeclaration&) const = default;
};

struct Action {
  std::string name;
  std::vector<TypedName> parameters;
  std::optional<Condition> precondition;
  std::optional<Effect> effect;
  SourceLocation location;
  bool operator==(const Action&) const = default;
};

struct DurativeAction {
  std::string name;
  std::vector<TypedName> parameters;
  std::vector<DurationConstraint> duration;
  std::optional<Condition> condition;
  std::optional<Effect> effect;
  SourceLocation location;
  bool operator==(const DurativeAction&) const = default;
};

// (:derived (name ?x - t ...) body)
struct DerivedPredicate {
  std::string name;
  std::vector<TypedName> parameters;
  Condition body;
  SourceLocation location;
  bool operator==(const DerivedPredicate&) const = default;
};

struct Domain {
  std::string name;
  std::vector<Requirement> requirements;
  std::vector<TypeDeclaration> types;
  std::vector<TypedName> constants;
  std::vector<PredicateDeclaration> predicates;
  std::vector<FunctionDeclaration> functions;
  std::optional<Condition> constraints;
  std::vector<Action> actions;
  std::vector<DurativeAction> durative_actions;
  std::vector<DerivedPredicate> derived_predicates;
  SourceLocation location;
  bool operator==(const Domain&) const = default;
};

// (= (f args) value) in :init.
struct NumericFact {
  FunctionTerm function;
  double value = 0.0;
  SourceLocation location;
  bool operator==(const NumericFact&) const = default;
};

// (at time literal) in :init. PDDL 2.2 allows literals only; a timed numeric
// value is parsed (so the checker can say so precisely) and then rejected.
struct TimedInitialLiteral {
  double time = 0.0;
  bool positive = true;
  Atom atom;
  std::optional<double> numeric_value;  // set for the invalid (at t (= (f) v))
  SourceLocation location;
  bool operator==(const TimedInitialLiteral&) const = default;
};

struct Metric {
  bool minimize = true;
  NumericExpression expression;
  SourceLocation location;
  bool operator==(const Metric&) const = default;
};

struct Problem {
  std::string name;
  std::string domain_name;
  SourceLocation domain_name_location;
  std::vector<Requirement> requirements;
  std::vector<TypedName> objects;
  std::vector<Atom> init;
  std::vector<NumericFact> numeric_init;
  std::vector<TimedInitialLiteral> timed_literals;
  std::optional<Condition> goal;
  std::optional<Condition> constraints;
  std::optional<Metric> metric;
  SourceLocation location;
  bool operator==(const Problem&) const = default;
};

const char* to_string(Comparison comparison);
const char* to_string(TimeSpecifier time);
const char* to_string(AssignOperator assign);

}  // namespace alplan::pddl
