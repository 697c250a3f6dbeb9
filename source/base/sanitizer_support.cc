// Compiled into the library only in the sanitizer build
// (RING_CONTACT_SANITIZE): dlclose() does nothing, so that every module
// loaded at run time stays loaded until the process ends. Open MPI loads its
// components (mca_*.so) with dlopen() at MPI_Init and unloads them at
// MPI_Finalize; what they keep allocated to the end is then reported by
// LeakSanitizer at exit without a module name, and cannot be told apart from
// a leak of ours. Kept loaded, their allocations carry the module's name and
// scripts/sanitize suppresses them by it. The library comes before libc in
// every executable's search order, so this definition is the one called.
extern "C" int
dlclose(void *)
{
  return 0;
}
