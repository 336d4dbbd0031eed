// How deep JSON text nests, found by one scan of its brackets before any parser builds (or a
// printer recurses through) the document: a text that nests past a limit is refused at the cost of
// reading it once. nlohmann's parser itself is not bounded: 60,000 nested [ ] given to --set took
// 104 s and 7.9 GB to pretty-print, and 200,000 in a capture record crashed the resume.
#pragma once

#include <string_view>

namespace liquid {

// The deepest nesting of arrays and objects in `text` (0 for a scalar), counting [ and { outside
// strings. Malformed text gets a number too; the parser that follows reports the syntax.
int json_nesting_depth(std::string_view text);

}  // namespace liquid
