// How the parser reads (parser.h): shared with its core (parser_core.h),
// apart from both so that neither includes the other.
#pragma once

namespace alplan::pddl {

struct ParserOptions {
  // Deeper nesting than this is reported instead of exhausting the stack.
  int max_nesting = 500;
};

}  // namespace alplan::pddl
