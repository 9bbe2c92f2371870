#pragma once
// Runs a callable that must throw SerialDeviceError and returns the error for inspection.
#include <mrolr/hw_serial/SerialError.h>

#include <gtest/gtest.h>

template <typename Fn>
mrolr::hw_serial::SerialDeviceError expectSerialError(Fn fn)
{
	try
	{
		fn();
	}
	catch (const mrolr::hw_serial::SerialDeviceError& e)
	{
		return e;
	}
	ADD_FAILURE() << "no SerialDeviceError";
	return mrolr::hw_serial::SerialDeviceError(mrolr::hw_serial::SerialDeviceError::Kind::Refused, "", "",
	                                    "none");
}
