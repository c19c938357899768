#include "report/number_format.hpp"

#include <cmath>
#include <locale>
#include <sstream>

namespace armstudy::report {

std::string format_sig(double value, int digits) {
  if (std::isnan(value)) return "n/a";
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(digits);
  os << value;
  return os.str();
}

}  // namespace armstudy::report
