// The checkpoint file's format version, shared by the writer (checkpoint.cpp) and the reader
// (checkpoint_load.cpp). 2: wall candidates refreshed apart from the particle list.
#pragma once

namespace paddy {
constexpr int kCheckpointVersion = 2;
}  // namespace paddy
