// printf-style formatting into a std::string, for log lines and messages.
#pragma once
#include <string>

namespace choc {

// The printf result as a string (any length).
std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

// Upper case, leading and trailing white space removed (names read from files).
std::string upperTrimmed(std::string s);

// A double as "%g" (6 significant digits; "inf", "nan" as printf writes them).
std::string shortNumber(double v);

}  // namespace choc
