// The input policy (io.h): what the kind of an input implies for the options it is meshed
// with, in one place for the CLI and the JavaScript package.
#include "acutemesh/io.h"

namespace acutemesh {

void applyInputPolicy(InputFormat format, bool hasRings, const ChosenOptions& chosen,
                      Options& options) {
  if (hasRings && !chosen.fill) options.fill = FillRule::EvenOdd;
  if (format == InputFormat::CgshopInstance) {
    options.exactSegments = true;
    if (!chosen.exactFeet) options.exactFeet = true;
  }
}

}  // namespace acutemesh
