// The fuzz test of the program's input, second half: the odd cases of
// the corpus (fuzz_inputs.h says what the corpus holds and what every run
// must do).
#include "fuzz_inputs.h"

int
main()
{
  run_fuzz(1, 2);
}
