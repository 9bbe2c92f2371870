#pragma once
/** mrolr-serial: the serial hardware path from the command line (docs/serial.md).
 *   mrolr-serial emulate [--sim CONFIG] [--world W.ini] [--truth-out T.json] [--seconds S]
 *                        [--delay-ms N] [--drop-probability P] [--json]
 *       builds the simulated lab of the world (default: CONFIG's [simulator] world_file; CONFIG is
 *       a mission file, default config/mission_sim.ini, whose world-side sections it reads),
 *       serves its base, head and arm on three pseudo-terminals and its stereo camera on a local
 *       TCP socket, and prints one line per device (`base /dev/pts/N`, `head …`, `arm …`,
 *       `camera 127.0.0.1:PORT`), until SIGINT / SIGTERM or for S seconds; then writes the truth
 *       to T.json (eval/MissionTruth.h) and the true pose after every base step to T.rawlog
 *       beside it (GROUND_TRUTH records, apps/TruthRecording.h), and exits 0;
 *   mrolr-serial send PORT VERB [FIELD...] [--baud B] [--timeout-ms T] [--retries R] [--json]
 *       sends one request to a device and prints the fields of its OK reply (exit 1 with the
 *       driver's error otherwise).
 * Results are left in the public fields. */

#include <mrolr/hw_serial/DeviceEmulator.h>

#include <string>
#include <vector>

namespace mrolr::apps
{
class SerialApp
{
 public:
	/** Parses argv (argv[0] first); throws util::UsageError for bad arguments; after --help,
	 * help_shown is set and run() does nothing. */
	void initialize(const std::vector<std::string>& args);
	/** Runs the command; returns the exit code (0, or 1 when the device failed). */
	int run();

	// --- parsed input ---
	std::string command;  ///< emulate | send
	bool json = false;
	bool help_shown = false;
	double seconds = 0;  ///< emulate: 0 = until SIGINT/SIGTERM
	hw_serial::FaultOptions faults;
	std::string sim_file;    ///< emulate: the mission file whose world-side sections it reads
	std::string world_file;  ///< emulate: empty = [simulator] world_file of sim_file
	std::string truth_out;   ///< emulate: T.json, written at the end (empty: not written)
	std::string port, verb;
	std::vector<std::string> fields;
	int baud = 9600, timeout_ms = 500, retries = 3;

	// --- results ---
	std::vector<std::string> ports;  ///< emulate: base, head, arm pty paths, camera address
	std::vector<std::string> reply;  ///< send: the OK reply's fields
	std::string error;               ///< send: the driver's error, when it failed
	size_t requests_served = 0;      ///< emulate: requests executed by all three

 private:
	int runEmulate();
	int runSend();
};

}  // namespace mrolr::apps
