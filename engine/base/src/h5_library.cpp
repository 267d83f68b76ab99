// HDF5 library set-up for every program that links the engine.
//
// A file whose last write fails (full disk, `ulimit -f`: EFBIG) makes H5Fclose fail, and HDF5
// 1.10 then keeps a half-closed file in its identifier table; its own clean-up at exit
// (H5_term_library, registered with atexit) crashes on it with SIGSEGV after paddy has already
// reported the error. Paddy closes every file it opens itself, so the library is told not to
// register that clean-up: a failed write then ends in the error message and the exit code, not
// a crash. H5dont_atexit must run before the first HDF5 call, hence a static initialiser.
//
// HDF5 also prints its whole error stack to stderr on every failed call (dozens of lines for a
// full disk). Paddy reports each failure itself, naming the file and the system's cause read from
// that stack (h5::systemCause), so the automatic printing is switched off: the user sees one line.
#include <hdf5.h>

namespace {

const bool kNoAtexit = [] {
  H5dont_atexit();
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  return true;
}();

}  // namespace
