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

std::string format_fixed(double value, int decimals) {
  if (std::isnan(value)) return "n/a";
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.setf(std::ios::fixed);
  os.precision(decimals);
  os << value;
  return os.str();
}

}  // namespace armstudy::report
