// How many texture fetches one run of a shader makes, read from its generated GLSL (issue 16: each
// pass's bound counts the fetches its draws make, fragments x fetches per fragment). Every call of
// a GLSL sampling function (texture*, texelFetch*, textureGather*; not textureSize or the query
// functions) counts once; a for loop whose trip count is fixed in the text (a literal start, limit
// and step, the counter assigned nowhere else) multiplies its body; functions called from main()
// add theirs. What the text cannot settle is a range, never a guess:
//  - a branch (if/else, switch, ?:, && and ||) counts its cheapest way into `least` and its
//    dearest into `most`;
//  - a loop with a data-dependent or uniform trip count, or one that may break, continue or
//    return, counts 0 times (or once for do-while) into `least` and makes `most` unbounded
//    (or trip count x body, when the trip count is known);
//  - code after a conditional `return` counts only into `most`.
// A `discard` does not shorten the count: the fragments GL_SAMPLES_PASSED counts are the ones that
// survived, and those ran the whole shader.
#pragma once

#include <string>

namespace fxport::xlate {

struct TextureFetches {
    int least = 0;           // fetches every run makes at least
    int most = 0;            // fetches a run makes at most (meaningless when unbounded)
    bool unbounded = false;  // a loop with an unknown trip count samples
    bool exact() const { return !unbounded && least == most; }
    // "47", ">=3" (unbounded), "3..13" (a range): what a timing table prints.
    std::string text() const;
};

// Fetches per run of main() in `glsl` (a whole shader as xlate emits it).
TextureFetches countTextureFetches(const std::string& glsl);

}  // namespace fxport::xlate
