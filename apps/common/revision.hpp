#pragma once
// The source revision the apps were built from: `git describe --always --dirty` at BUILD time
// ("unknown" outside git). Defined in a generated source (cmake/WriteRevision.cmake) compiled
// into the one small target im_revision, so a new revision relinks the apps and recompiles
// nothing else.

namespace indoormap {

/// e.g. "1129137" or "v0.1-12-g1129137-dirty"; "unknown" when built outside git.
const char* source_revision();

}  // namespace indoormap
