// A deliberate data race in an OpenMP loop. scripts/sanitize.sh thread runs it first and requires
// ThreadSanitizer (with the Archer OpenMP tool) to report it: this proves that the race check of
// the force loop is able to fail, i.e. that the OpenMP runtime is seen by the sanitizer.
#include <cstdio>

int main() {
  long sum = 0;
#pragma omp parallel for num_threads(2)
  for (int i = 0; i < 1000; ++i) sum += i;  // unsynchronised read-modify-write: a race
  std::printf("%ld\n", sum);
  return 0;
}
