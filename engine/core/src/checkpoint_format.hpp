// The checkpoint file's format version, shared by the writer (checkpoint.cpp) and the reader
// (checkpoint_load.cpp). 2: wall candidates refreshed apart from the particle list. 3: the
// threads' split of the contacts' owners (forces.cpp), so that a resumed run sums its forces in
// the same order.
#pragma once

namespace paddy {
constexpr int kCheckpointVersion = 3;
}  // namespace paddy
