// The check every bad-input test makes: f must throw pumpd::InvalidParameter whose what() starts
// with "<name> = " and contains `allowed` (the parameter named, then its allowed range); and the
// message itself, for tests that read figures out of it.
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <functional>
#include <string>

#include "error.h"

namespace pumpd::test
{
  inline void expect_invalid(const std::function<void()> &f, const std::string &name, const std::string &allowed)
  {
    try
      {
        f();
        ADD_FAILURE() << "no exception; expected InvalidParameter naming \"" << name << "\"";
      }
    catch (const InvalidParameter &e)
      {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(name + " = ", 0), 0u) << "message does not start with the name \"" << name
                                                   << "\": " << what;
        EXPECT_NE(what.find(allowed), std::string::npos) << "no \"" << allowed << "\" in: " << what;
      }
    catch (const std::exception &e)
      {
        ADD_FAILURE() << "wrong exception type; expected InvalidParameter naming \"" << name
                      << "\", got: " << e.what();
      }
  }

  /// The message of the InvalidParameter f throws; "" if it throws none.
  inline std::string invalid_message(const std::function<void()> &f)
  {
    try
      {
        f();
      }
    catch (const InvalidParameter &e)
      {
        return e.what();
      }
    return "";
  }
} // namespace pumpd::test
