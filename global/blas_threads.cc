#include "blas_threads.h"

#include <dlfcn.h>

#include <mutex>

namespace pumpd::global
{
  void use_single_threaded_blas()
  {
    static std::once_flag once;
    std::call_once(once, [] {
      using GetParallel = int (*)();
      using SetThreads  = void (*)(int);
      const auto parallel = reinterpret_cast<GetParallel>(dlsym(RTLD_DEFAULT, "openblas_get_parallel"));
      const auto set      = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
      constexpr int own_threads = 1; // openblas_get_parallel: 0 sequential, 1 pthreads, 2 OpenMP
      if (parallel && set && parallel() == own_threads)
        set(1);
    });
  }
} // namespace pumpd::global
