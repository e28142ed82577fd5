/*---------------------------------------------------------------------------*\
Description
    The report of where the cloud's time goes (pathTimes): the paths of an
    interval add up to its CPU time from the start to the stop, shared by
    the laps' clock time, each lap going to the path it closes; a lap
    outside an interval takes the CPU time since the last stop or lap; the
    report line lists the paths that took at least half a millisecond with
    their shares.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "pathTimes.H"
#include "OStringStream.H"

#include <ctime>

using namespace Foam;
using namespace Foam::polymer;

namespace
{

// Spend about the given CPU seconds
void spin(const double seconds)
{
    const std::clock_t end = std::clock() + std::clock_t(seconds*CLOCKS_PER_SEC);
    volatile double x = 0;
    while (std::clock() < end)
    {
        x = x + 1;
    }
}

} // End anonymous namespace


TEST(pathTimes, LapsAddUpAndGoToTheirPaths)
{
    const std::clock_t before = std::clock();
    pathTimes times;
    times.start();
    spin(0.02);
    times.lap(pathTimes::integrate);
    spin(0.01);
    times.lap(pathTimes::collide);
    times.lap(pathTimes::write);
    const scalar interval = times.stop();
    const std::clock_t after = std::clock();

    // The interval's CPU time, all of it to the paths lapped
    scalar sum = 0;
    for (label p = 0; p < pathTimes::nPaths; ++p)
    {
        EXPECT_GE(times.seconds(pathTimes::path(p)), 0);
        sum += times.seconds(pathTimes::path(p));
    }
    EXPECT_NEAR(sum, interval, 1e-12*interval);
    EXPECT_GE(interval, 0.03);
    EXPECT_LE(interval, scalar(after - before)/CLOCKS_PER_SEC);

    // Shared by the laps' clock time: 20 ms, 10 ms and none on a machine
    // that runs the test alone
    EXPECT_GT
    (
        times.seconds(pathTimes::integrate),
        times.seconds(pathTimes::collide)
    );
    EXPECT_GT(times.seconds(pathTimes::collide), 0.005);
    EXPECT_LT(times.seconds(pathTimes::write), 5e-4);
    EXPECT_EQ(times.seconds(pathTimes::constrain), 0);

    // Outside an interval a lap takes the CPU time since the stop
    spin(0.01);
    times.lap(pathTimes::functions);
    EXPECT_GE(times.seconds(pathTimes::functions), 0.01);
}


TEST(pathTimes, ReportListsThePathsThatTookTime)
{
    pathTimes times;
    times.start();
    spin(0.03);
    times.lap(pathTimes::locate);
    spin(0.01);
    times.lap(pathTimes::constrain);
    times.stop();

    OStringStream os;
    times.writeReport(os);
    const std::string line = os.str();
    EXPECT_EQ(line.find("    CPU by path, s (share), all processors: "), 0u)
        << line;
    EXPECT_NE(line.find("locate and sample 0.0"), std::string::npos) << line;
    EXPECT_NE(line.find("constrain 0.0"), std::string::npos) << line;
    EXPECT_EQ(line.find("integrate"), std::string::npos) << line;
    EXPECT_EQ(line.find("write"), std::string::npos) << line;

    // Shares: about 75 % and 25 %, rounded to whole percent
    const auto share = [&](const std::string& name)
    {
        const std::size_t at = line.find('(', line.find(name));
        return std::stoi(line.substr(at + 1));
    };
    EXPECT_NEAR(share("locate and sample") + share("constrain"), 100, 1);
    EXPECT_GT(share("locate and sample"), share("constrain"));
}


// ************************************************************************* //
