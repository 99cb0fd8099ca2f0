// The threads of the BLAS under the global solve (CHOLMOD's supernodes, UMFPACK's fronts).
#pragma once

namespace pumpd::global
{
  /// Runs the BLAS on one thread where it is OpenBLAS built with its own threads (Debian's
  /// libopenblas0-pthread, found at run time); nothing happens with another BLAS or an OpenMP
  /// build of OpenBLAS, whose thread count is the OpenMP one the PD kernel uses. The supernodal
  /// blocks of a global problem are small: OpenBLAS's threads cost more than they give there,
  /// keep polling a core the PD kernel's threads then wait for, and split the sums by the number
  /// of cores, so that the solution's last bits, and with them a coupled crack path, would depend
  /// on the machine's core count.
  void use_single_threaded_blas();
} // namespace pumpd::global
