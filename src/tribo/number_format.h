// Numbers in error messages, printed as printf's "%g" prints them (6 significant digits).
#pragma once

#include <cstdio>
#include <string>

namespace runin::tribo {

inline std::string format_g(double x)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

}    // namespace runin::tribo
