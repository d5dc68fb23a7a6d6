// What the Chapter 5 scenes share: the principal moments at O and f, named as in [P].
#pragma once

#include "scene.hpp"

namespace ch5 {

// --A --B --C --f, each a finite number > 0; the rules between the moments (A < B < C,
// A + B >= C) are checked by rigid::moments(). Returns opts, so more options can follow.
inline kit::Options& moment_options(kit::Options& opts) {
    return opts.real("A", 1.0, "smallest principal moment at O", kit::positive())
        .real("B", 1.5, "intermediate principal moment at O", kit::positive())
        .real("C", 2.2, "largest principal moment at O (A + B >= C)", kit::positive())
        .real("f", 1.0, "f = g L mu", kit::positive());
}

}  // namespace ch5
