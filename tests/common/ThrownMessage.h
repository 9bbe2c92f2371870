#pragma once
// The message of the exception a call throws: what the tests of bad input read.
#include <string>
#include <utility>

namespace mrolr::test_support
{
/** The what() of the @p E that @p f throws, or @p none when it throws nothing. An exception of
 * another type is not caught, so the test fails on it. */
template <class E, class F>
std::string messageOf(F&& f, const std::string& none = "")
{
	try
	{
		std::forward<F>(f)();
	}
	catch (const E& e)
	{
		return e.what();
	}
	return none;
}

}  // namespace mrolr::test_support
