#include "explicit_run.h"

#include "checkpoint.h"
#include "error.h"

namespace pumpd::local
{
  void run_explicit(const VelocityVerlet &integrator, State &s, const BoundaryLayer &layer,
                    const ExplicitRun &run)
  {
    if (run.keep_every < 1)
      throw InvalidParameter("keep_every", "0", "must be >= 1 (steps between copies of the good state)");
    State good = s;
    for (std::size_t n = 1; n <= run.steps; ++n)
      {
        const double ramp = run.ramp ? run.ramp(n) : double(n) / double(run.steps);
        try
          {
            integrator.step(s, layer, ramp);
          }
        catch (const NonFiniteState &e)
          {
            std::string message = e.what();
            if (!run.failure_checkpoint.empty())
              {
                write_checkpoint(run.failure_checkpoint, integrator.model(), good);
                message += "; run stopped, last good state (step " + std::to_string(good.step) +
                           ") saved to " + run.failure_checkpoint;
              }
            throw NonFiniteState(message);
          }
        if (n % run.keep_every == 0)
          good = s;
        if (run.observer)
          run.observer(s, n);
      }
  }
} // namespace pumpd::local
