/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    Test-polymerCloudStatistics

Description
    Statistical tests of a polymerCloud against exact equilibrium and
    diffusion results (/work/shared/validation.md), free draining, no flow:

    trimer  (N = 3)   <cos^2 theta> = 0.32102 of rigid constraints, and not
                      the freely jointed 1/3; <P2> = -0.01847
    chain   (N = 10)  <Ree^2> = (N-1) a^2, <Rg^2> = a^2 (N^2-1)/(6N)
    ring    (N = 6)   hexagons from a file
    all               <K> = f kT/2 (f = 2N+1 open, 2N ring), <M Vcm^2> = 3kT,
                      MSD(t) = 6D[t - tau_m(1 - e^{-t/tau_m})], D = kT/(N zeta)

    Units: a = m = zeta = kT = 1, so tau_m = m/zeta = 1; the default
    deltaT = 0.01 tau_m resolves the inertia, which the distribution of
    rigid constraints needs. Chains are independent blocks (see
    statisticalCheck.H): each check is mean +- SE against the exact value,
    within 4 SE. Prints one PASS/FAIL line per check; exits 1 if any failed.

Usage
    Test-polymerCloudStatistics -case <dir> -scenario trimer|chain|ring
        [-constraint RATTLE|newton] [-deltaT 0.01] [-nChains N] [-seed S]
        [-equilibration T] [-sampling T]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "fvMesh.H"
#include "OFstream.H"
#include "IStringStream.H"
#include "polymerCloud.H"
#include "statisticalCheck.H"
#include "evolveStep.H"
#include <regex>
#include <vector>

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- Regular N-gons of side 1 in constant/polymerChains, one per chain
void writePolygons(const Time& runTime, const label nChains, const label n)
{
    const fileName dir = runTime.path()/runTime.constant();
    mkDir(dir);
    OFstream os(dir/"polymerChains");
    os.precision(17);
    os  << "FoamFile { version 2.0; format ascii; class dictionary;"
        << " object polymerChains; }\nchains\n(\n";
    const scalar R = 0.5/std::sin(M_PI/n);
    for (label c = 0; c < nChains; ++c)
    {
        const point centre(5*(c % 20), 5*((c/20) % 20), 5*(c/400));
        os  << "{ chainType test; positions (";
        for (label k = 0; k < n; ++k)
        {
            const scalar phi = 2*M_PI*k/n;
            os  << ' ' << centre + R*vector(std::cos(phi), std::sin(phi), 0);
        }
        os  << " ); }\n";
    }
    os  << ");\n";
}

//- Diagnostics of a chain whose constraint solve failed: the rods' unit
//  vectors' neighbour products and det of the Laub (constraint) matrix
//  T = tridiag(-u_k.u_{k+1}, 2, -u_k.u_{k+1}) (cyclic for a ring), which is
//  singular when all rods are parallel
void describeChain(const polymerChains& chains, const label c)
{
    const chainType& t = chains.type(c);
    const label n = t.nBeads(), nr = t.nRods(), s = chains.start(c);
    const List<vector>& x = chains.positions();
    List<vector> u(nr);
    for (label k = 0; k < nr; ++k)
    {
        const vector r = x[s + (k + 1)%n] - x[s + k];
        u[k] = r/mag(r);
    }
    std::vector<std::vector<double>> T(nr, std::vector<double>(nr, 0.0));
    for (label k = 0; k < nr; ++k)
    {
        T[k][k] = 2;
        if (k + 1 < nr || t.ring())
        {
            const label j = (k + 1)%nr;
            T[k][j] = T[j][k] = -(u[k] & u[j]);
        }
    }
    double det = 1;
    for (label i = 0; i < nr; ++i)
    {
        label p = i;
        for (label r = i + 1; r < nr; ++r)
            if (std::abs(T[r][i]) > std::abs(T[p][i])) p = r;
        std::swap(T[i], T[p]);
        if (p != i) det = -det;
        det *= T[i][i];
        if (T[i][i] == 0) break;
        for (label r = i + 1; r < nr; ++r)
        {
            const double f = T[r][i]/T[i][i];
            for (label q = i; q < nr; ++q) T[r][q] -= f*T[i][q];
        }
    }
    Info<< "Chain " << chains.globalId(c) << ": rod error "
        << chains.maxRodLengthError(c) << ", u_k.u_k+1:";
    for (label k = 0; k < (t.ring() ? nr : nr - 1); ++k)
    {
        Info<< ' ' << (u[k] & u[(k + 1)%nr]);
    }
    Info<< nl << "    det(constraint matrix) " << det
        << " (regular hexagon 42.19; singular: all rods parallel)"
        << nl << "    positions " << SubList<vector>(x, n, s) << endl;
}

//- Cloud properties of the scenario
dictionary properties
(
    const word& scenario,
    const word& constraint,
    const label nChains,
    const label nBeads,
    const label seed,
    const bool fixman
)
{
    const bool ring = (scenario == "ring");
    OStringStream os;
    os  << "solution { active true; seed " << seed << "; }\n"
        << "chainTypes { test { nBeads " << nBeads << "; rodLength 1;"
        << " beadMass 1; friction 1; kT 1; ring " << (ring ? "true" : "false")
        << "; } }\n"
        << "subModels {\n"
        << "    integration exactOU; constraint " << constraint << ";\n"
        << "    collision none; wall none; flow none;\n"
        << "    forces (" << (fixman ? "fixman" : "") << ");\n"
        << "    initialisation " << (ring ? "file" : "randomWalk") << ";\n"
        << "    randomWalkCoeffs { min (-50 -50 -50); max (50 50 50);"
        << " chains { test " << nChains << "; } }\n"
        << "    fileCoeffs { file polymerChains; tolerance 1e-9; }\n"
        << "    " << constraint << "Coeffs { tolerance 1e-10;"
        << " velocityTolerance 1e-10; }\n"
        << "}\n";
    IStringStream is(os.str());
    return dictionary(is);
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::addOption("scenario", "name", "trimer | chain | ring");
    argList::addOption("constraint", "model", "RATTLE (default) | newton");
    argList::addOption("deltaT", "scalar", "time step (default 0.01)");
    argList::addOption("nChains", "label", "number of chains");
    argList::addOption("seed", "label", "noise seed (default 1)");
    argList::addOption("equilibration", "scalar", "time before sampling");
    argList::addOption("sampling", "scalar", "time of sampling");
    argList::addBoolOption
    (
        "fixman",
        "add the Fixman potential: freely jointed statistics expected"
    );

    #include "setRootCase.H"
    #include "createTime.H"

    fvMesh mesh
    (
        IOobject
        (
            fvMesh::defaultRegion,
            runTime.timeName(),
            runTime,
            IOobject::MUST_READ
        )
    );

    const word scenario = args.get<word>("scenario");
    const word constraint = args.getOrDefault<word>("constraint", "RATTLE");
    const scalar deltaT = args.getOrDefault<scalar>("deltaT", 0.01);
    const label seed = args.getOrDefault<label>("seed", 1);
    const bool fixman = args.found("fixman");

    label nBeads = 3, nChains = 2000;
    scalar equilibration = 10, sampling = 100;
    if (scenario == "chain")
    {
        nBeads = 10; nChains = 1000; equilibration = 20; sampling = 60;
    }
    else if (scenario == "ring")
    {
        nBeads = 6; nChains = 1000; equilibration = 10; sampling = 50;
    }
    else if (scenario != "trimer")
    {
        FatalErrorInFunction << "Unknown scenario " << scenario << exit(FatalError);
    }
    nChains = args.getOrDefault<label>("nChains", nChains);
    equilibration = args.getOrDefault<scalar>("equilibration", equilibration);
    sampling = args.getOrDefault<scalar>("sampling", sampling);

    const bool ring = (scenario == "ring");
    if (ring)
    {
        writePolygons(runTime, nChains, nBeads);
    }

    polymerCloud cloud
    (
        "polymerCloud",
        mesh,
        properties(scenario, constraint, nChains, nBeads, seed, fixman)
    );
    cloud.writeSummary(Info);

    const polymerChains& chains = cloud.chains();
    const label nc = chains.nChains();
    const label N = nBeads;
    const scalar tauM = 1, D = 1.0/N;   // m/zeta, kT/(N zeta)
    const label f = ring ? 2*N : 2*N + 1;

    const std::string name =
        "stat." + scenario + "." + constraint + (fixman ? ".fixman" : "");
    Info<< name.c_str() << ": " << nc << " chains of " << N << " beads, deltaT "
        << deltaT << ", equilibration " << equilibration << ", sampling "
        << sampling << nl << endl;

    runTime.setDeltaT(deltaT);
    const label nEquilibration = std::lround(equilibration/deltaT);
    const label nSampling = std::lround(sampling/deltaT);
    const label sampleEvery = max(1, std::lround(0.5/deltaT));

    // MSD lags (time after the end of equilibration)
    List<scalar> lags({1.0, 5.0, std::round(sampling/4), sampling});
    List<label> lagSteps(lags.size());
    forAll(lags, i) lagSteps[i] = std::lround(lags[i]/deltaT);

    blockMean cos2(nc), p2(nc), ree2(nc), rg2(nc), kinetic(nc), mv2(nc);
    PtrList<blockMean> msd(lags.size());
    forAll(lags, i) msd.set(i, new blockMean(nc));

    List<vector> com0(nc);

    FatalError.throwExceptions(true);

    for (label step = 1; step <= nEquilibration + nSampling; ++step)
    {
        ++runTime;
        std::string msg;
        if (!evolveStep(cloud, name, msg))
        {
            std::smatch match;
            if (std::regex_search(msg, match, std::regex("chain ([0-9]+)")))
            {
                const label id = std::stoi(match[1]);
                for (label c = 0; c < chains.nChains(); ++c)
                {
                    if (chains.globalId(c) == id) describeChain(chains, c);
                }
            }
            return 1;
        }

        const label sampleStep = step - nEquilibration;
        if (sampleStep == 0)
        {
            for (label c = 0; c < nc; ++c) com0[c] = chains.centreOfMass(c);
        }
        if (sampleStep <= 0) continue;

        forAll(lagSteps, i)
        {
            if (sampleStep != lagSteps[i]) continue;
            for (label c = 0; c < nc; ++c)
            {
                msd[i].add(c, magSqr(chains.centreOfMass(c) - com0[c]));
            }
        }

        if (sampleStep % sampleEvery) continue;

        const List<vector>& x = chains.positions();
        const List<vector>& v = chains.velocities();
        for (label c = 0; c < nc; ++c)
        {
            const label s = chains.start(c);
            vector momentum(Zero);
            for (label i = s; i < chains.end(c); ++i) momentum += v[i];

            kinetic.add(c, chains.kineticEnergy(c));
            mv2.add(c, magSqr(momentum)/N);     // M Vcm^2 = |P|^2/M
            rg2.add(c, chains.radiusOfGyrationSqr(c));
            if (!ring) ree2.add(c, chains.endToEndSqr(c));
            if (N == 3)
            {
                const vector b1 = x[s + 1] - x[s], b2 = x[s + 2] - x[s + 1];
                const scalar ct = (b1 & b2)/(mag(b1)*mag(b2));
                cos2.add(c, ct*ct);
                p2.add(c, 1.5*ct*ct - 0.5);
            }
        }
    }

    Info<< "Constraint solves: " << cloud.constraint().totalCount().solves
        << ", iterations per solve "
        << scalar(cloud.constraint().totalCount().iterations)
          /max(cloud.constraint().totalCount().solves, label(1))
        << ", failures " << cloud.constraint().totalCount().failures
        << ", sub-stepped chains " << cloud.constraint().totalCount().subStepped
        << ", final rod error " << chains.maxRodLengthError() << nl << endl;

    double m, se;

    std::printf
    (
        "%s %s.rods: max rod error %.3g (<= 1e-9), constraint failures %d\n",
        (chains.maxRodLengthError() <= 1e-9
      && cloud.constraint().totalCount().failures == 0) ? "PASS" : "FAIL",
        name.c_str(), chains.maxRodLengthError(),
        int(cloud.constraint().totalCount().failures)
    );
    if (!(chains.maxRodLengthError() <= 1e-9
      && cloud.constraint().totalCount().failures == 0)) ++nFailedChecks();

    if (N == 3 && fixman)
    {
        // The Fixman potential cancels the rigid metric: freely jointed
        cos2.result(m, se);
        checkMean(name + ".cos2", "<cos^2 theta>", m, se, 1.0/3);
        checkDistinct(name + ".cos2NotRigid", "<cos^2 theta>", m, se, 0.32102);
        p2.result(m, se);
        checkMean(name + ".P2", "<P2(cos theta)>", m, se, 0);
    }
    else if (N == 3)
    {
        cos2.result(m, se);
        checkMean(name + ".cos2", "<cos^2 theta>", m, se, 0.32102);
        checkDistinct(name + ".cos2NotFreelyJointed", "<cos^2 theta>", m, se, 1.0/3);
        p2.result(m, se);
        checkMean(name + ".P2", "<P2(cos theta)>", m, se, -0.01847);
    }
    if (!ring)
    {
        ree2.result(m, se);
        checkMean(name + ".Ree2", "<Ree^2>/a^2", m, se, N - 1);
        rg2.result(m, se);
        checkMean(name + ".Rg2", "<Rg^2>/a^2", m, se, (N*N - 1.0)/(6*N));
    }
    kinetic.result(m, se);
    checkMean(name + ".equipartition", "<K>/kT (f = " + std::to_string(f) + ")", m, se, 0.5*f);
    mv2.result(m, se);
    checkMean(name + ".comKinetic", "<M Vcm^2>/kT", m, se, 3);

    forAll(lags, i)
    {
        const scalar t = lags[i];
        msd[i].result(m, se);
        checkMean
        (
            name + ".msd(t=" + std::to_string(int(std::lround(t))) + ")",
            "MSD/a^2", m, se, 6*D*(t - tauM*(1 - std::exp(-t/tauM)))
        );
    }

    Info<< nl << "End" << nl << endl;

    return nFailedChecks() ? 1 : 0;
}


// ************************************************************************* //
