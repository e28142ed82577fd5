/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    Test-polymerCloudConfinement

Description
    Ideal bead-rod chains between two parallel hard walls (validation.md,
    Confinement): the equilibrium density across the slit against the exact
    freely jointed result.

    The case's mesh is a slit (tests/cases/wallSlit: walls at z = 0 and
    z = h, the x-y sides far away). Chains of N beads (a = m = zeta = kT = 1)
    with exactOU, newton, forces (fixman) (so that the equilibrium is the
    freely jointed chain's), wall meshFaces (or levelSet with -wall),
    collision none, flow none, started by randomWalk inside the mesh (first
    bead uniform, chains with a bead outside drawn again: already the
    equilibrium distribution).

    Exact result: the transfer integral of slitExact.H (the densities of
    each bead across the slit and the partition coefficient K), checked by
    Monte Carlo.

    The measured densities of the end beads (0 and N-1) and of the inner
    beads are histograms (nBins bins across the slit) averaged per chain
    over time; chains are independent blocks (statisticalCheck.H) and each
    bin is checked within 4 SE. Every bead must stay in [0, h].

    Partition coefficient of the simulation (reported, not checked): from
    an end bead farther than (N-1)a from both walls the other beads cannot
    reach a wall, g_{N-1} = 1, so the end bead's density g_{N-1}(z)/(h K)
    is the constant 1/(h K) in the central region |z - h/2| < h/2 - (N-1)a
    (a slit wider than 2(N-1)a). With f the fraction of end-bead samples
    in that region of width L, p_centre = f/L and
        K_sim = 1/(h p_centre) = L/(h f),   SE(K_sim) = K_sim SE(f)/f
    (f a block mean over the chains).
    levelSet (-wall levelSet -clearance c) keeps the beads c from the
    walls: they see a slit of width h' = h - 2c, so the central region is
    that of h' and K_sim estimates h' K(h')/h (the concentration in the
    slit over the bulk's, h the true width), reported next to K(h) to
    separate the clearance's bias from the rest. The profiles are against
    the true walls' (with the clearance's bias).
    The CPU time of the chains' evolution per step and per bead-step is
    reported with it.

    Prints one PASS/FAIL line per check; exits 1 if any failed.

Usage
    Test-polymerCloudConfinement -case <slit case> [-nBeads 4] [-nChains 1000]
        [-deltaT 0.01] [-equilibration 5] [-sampling 100] [-bins 8]
        [-seed 1] [-constraint newton] [-noFixman]
        [-wallInteraction rebound] [-checkProfile]
        [-wall meshFaces | -wall levelSet -clearance <c>]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "fvMesh.H"
#include "IStringStream.H"
#include "polymerCloud.H"
#include "statisticalCheck.H"
#include "evolveStep.H"
#include "cpuTimeCxx.H"
#include "slitExact.H"

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

dictionary properties
(
    const label nChains,
    const label nBeads,
    const label seed,
    const word& constraint,
    const bool fixman,
    const boundBox& bb,
    const word& wall,
    const scalar clearance,
    const word& wallInteraction
)
{
    OStringStream os;
    const scalar xMin = bb.min().x() + 0.2*bb.span().x();
    const scalar xMax = bb.max().x() - 0.2*bb.span().x();
    const scalar yMin = bb.min().y() + 0.2*bb.span().y();
    const scalar yMax = bb.max().y() - 0.2*bb.span().y();
    os  << "solution { active true; seed " << seed << "; }\n"
        << "chainTypes { test { nBeads " << nBeads << "; rodLength 1;"
        << " beadMass 1; friction 1; kT 1; } }\n"
        << "subModels {\n"
        << "    integration exactOU; constraint " << constraint << ";\n"
        << "    collision none; wall " << wall << "; flow none;\n"
        << "    " << wall << "Coeffs { patchInteraction { walls "
        << wallInteraction << "; }";
    if (wall == "levelSet")
    {
        os  << " clearance " << clearance << ';';
    }
    os  << " }\n"
        << "    forces (" << (fixman ? "fixman" : "") << ");\n"
        << "    initialisation randomWalk;\n"
        << "    randomWalkCoeffs { min (" << xMin << ' ' << yMin << ' '
        << bb.min().z() << "); max (" << xMax << ' ' << yMax << ' '
        << bb.max().z() << "); insideMesh true; chains { test " << nChains
        << "; } }\n"
        << "    " << constraint << "Coeffs { tolerance 1e-10;"
        << " velocityTolerance 1e-10; }\n"
        << "}\n";
    IStringStream is(os.str());
    return dictionary(is);
}

} // End anonymous namespace


//- A profile bin: checked (PASS/FAIL) with -checkProfile, otherwise
//  reported (INFO) with its deviation
void reportBin
(
    const bool check,
    const std::string& name,
    const std::string& label,
    const double m,
    const double se,
    const double expected
)
{
    if (check)
    {
        checkMean(name, label, m, se, expected);
        return;
    }
    std::printf
    (
        "INFO %s: %s = %.4f +- %.2g (SE), exact %.4f, deviation %.1f SE\n",
        name.c_str(), label.c_str(), m, se, expected, (m - expected)/se
    );
}


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::addOption("nBeads", "label", "beads per chain (default 4)");
    argList::addOption("nChains", "label", "number of chains (default 1000)");
    argList::addOption("deltaT", "scalar", "time step (default 0.01)");
    argList::addOption("equilibration", "scalar", "time before sampling (5)");
    argList::addOption("sampling", "scalar", "time of sampling (100)");
    argList::addOption("bins", "label", "bins across the slit (default 8)");
    argList::addOption("seed", "label", "noise seed (default 1)");
    argList::addOption("constraint", "model", "newton (default) | RATTLE");
    argList::addBoolOption("noFixman", "without the Fixman potential");

    argList::addOption
    (
        "wallInteraction",
        "type",
        "the walls' patchInteraction: rebound (default) | reject"
    );
    argList::addOption
    (
        "wall",
        "model",
        "bead-wall model: meshFaces (default) | levelSet (with -clearance)"
    );
    argList::addOption
    (
        "clearance",
        "scalar",
        "levelSet's clearance, the beads' least distance from a wall"
    );
    argList::addBoolOption
    (
        "checkProfile",
        "fail on the equilibrium profile (known to deviate: the paper's"
        " single-bead rebound; without it the profile is reported only)"
    );

    #include "setRootCase.H"
    const bool checkProfile = args.found("checkProfile");

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

    const label N = args.getOrDefault<label>("nBeads", 4);
    const label nChainsWanted = args.getOrDefault<label>("nChains", 1000);
    const scalar deltaT = args.getOrDefault<scalar>("deltaT", 0.01);
    const scalar equilibration = args.getOrDefault<scalar>("equilibration", 5);
    const scalar sampling = args.getOrDefault<scalar>("sampling", 100);
    const label nBins = args.getOrDefault<label>("bins", 8);
    const label seed = args.getOrDefault<label>("seed", 1);
    const word constraint = args.getOrDefault<word>("constraint", "newton");
    const bool fixman = !args.found("noFixman");
    const word wallInteraction =
        args.getOrDefault<word>("wallInteraction", "rebound");
    const word wall = args.getOrDefault<word>("wall", "meshFaces");
    if (wall != "meshFaces" && wall != "levelSet")
    {
        FatalErrorInFunction
            << "-wall " << wall << ": meshFaces or levelSet"
            << exit(FatalError);
    }

    // levelSet has no default clearance (a bead's radius): ask for it
    const bool levelSet = (wall == "levelSet");
    if (levelSet != args.found("clearance"))
    {
        FatalErrorInFunction
            << "-clearance goes with -wall levelSet (and levelSet needs it)"
            << exit(FatalError);
    }
    const scalar clearance =
        levelSet ? args.get<scalar>("clearance") : scalar(0);

    const boundBox& bb = mesh.bounds();
    const scalar z0 = bb.min().z();
    const scalar h = bb.span().z();
    const scalar a = 1;

    // meshFaces keeps the names the test suite knows
    const std::string name =
        "stat.slit." + (levelSet ? "levelSet." : std::string())
      + wallInteraction;

    // Exact freely jointed result
    const label M = 600*nBins;
    const double dz = h/M;
    const auto g = transferIterates(N, a, h, M);
    const double K = integral(g[N - 1], 0, M, dz)/h;

    const std::vector<double> endExact = beadProfile(g, 0, nBins, dz);
    const label kInner = N/2;
    const std::vector<double> innerExact = beadProfile(g, kInner, nBins, dz);

    // The slit the beads see: levelSet's zero is a clearance from each
    // wall. Its K as a fraction of the true width's: the partition
    // coefficient of hard walls at the level set's zero
    const double hSeen = h - 2*clearance;
    double Kseen = K;
    if (levelSet)
    {
        const auto gSeen = transferIterates(N, a, hSeen, M);
        Kseen = integral(gSeen[N - 1], 0, M, hSeen/M)/h;
    }

    // The end bead's central region, where g_{N-1} = 1 in the slit seen
    const double centreHalf = 0.5*hSeen - (N - 1)*a;
    const bool hasCentre = (centreHalf > 0);

    // Monte Carlo check of K, and Casassa's asymptote for information
    double KmcSE = 0;
    const double Kmc = monteCarloPartition(N, a, h, 1000000, KmcSE);
    const double Kcasassa = casassaPartition(N, a, h);

    Info<< name.c_str() << ": chains of " << N << " beads (a = 1) between walls"
        << " at z = " << z0 << " and " << z0 + h << " (h = " << h << ")" << nl
        << "    exact (transfer integral, " << M << " intervals): K = " << K
        << "; Monte Carlo K = " << Kmc << " +- " << KmcSE
        << "; Casassa's long-chain asymptote " << Kcasassa << nl;
    if (levelSet)
    {
        Info<< "    levelSet, clearance " << clearance << ": the beads see"
            << " a slit of width " << hSeen << ", K " << Kseen
            << " (its concentration over the bulk's, width " << h << ")"
            << nl;
    }
    if (hasCentre)
    {
        Info<< "    end beads' central region (g_" << N - 1 << " = 1): "
            << 0.5*h - centreHalf << " < z - " << z0 << " < "
            << 0.5*h + centreHalf << nl;
    }
    Info<< "    exact end-bead bin probabilities:";
    for (const double p : endExact) Info<< ' ' << p;
    Info<< nl << "    exact bead-" << kInner << " bin probabilities:";
    for (const double p : innerExact) Info<< ' ' << p;
    Info<< nl << endl;

    polymerCloud cloud
    (
        "polymerCloud",
        mesh,
        properties
        (
            nChainsWanted, N, seed, constraint, fixman, bb, wall,
            clearance, wallInteraction
        )
    );
    cloud.writeSummary(Info);

    const polymerChains& chains = cloud.chains();
    const label nc = chains.nChains();

    runTime.setDeltaT(deltaT);
    const label nEquilibration = std::lround(equilibration/deltaT);
    const label nSampling = std::lround(sampling/deltaT);
    const label sampleEvery = max(1, std::lround(0.5/deltaT));

    PtrList<blockMean> endBins(nBins), innerBins(nBins);
    for (label b = 0; b < nBins; ++b)
    {
        endBins.set(b, new blockMean(nc));
        innerBins.set(b, new blockMean(nc));
    }
    blockMean rg2(nc);

    // Fraction of end-bead samples in the central region
    blockMean centre(nc);

    // The initial chains (randomWalk inside the mesh: the equilibrium
    // distribution), one sample a chain (its first bead; the chains are
    // independent, the two ends of one are not): a check of the expected
    // values independent of the dynamics
    List<label> initialEnd(nBins, Zero);
    {
        const List<vector>& x = chains.positions();
        for (label c = 0; c < nc; ++c)
        {
            const scalar z = (x[chains.start(c)].z() - z0)/h;
            ++initialEnd[min(max(label(z*nBins), label(0)), nBins - 1)];
        }
    }

    label nOutside = 0, nOutsideSteps = 0;
    scalar worstOutside = 0, maxRodError = 0;

    // The cost of the chains' evolution alone; std::clock's resolution
    // (cpuTimeCxx): a step takes about a millisecond, below the 0.01 s
    // tick of cpuTime (times())
    cpuTimeCxx timer;
    double evolveSeconds = 0;

    FatalError.throwExceptions(true);

    for (label step = 1; step <= nEquilibration + nSampling; ++step)
    {
        ++runTime;
        std::string message;
        timer.cpuTimeIncrement();
        const bool evolved = evolveStep(cloud, name, message);
        evolveSeconds += timer.cpuTimeIncrement();
        if (!evolved)
        {
            return 1;
        }
        if (chains.nChains() != nc)
        {
            std::printf
            (
                "FAIL %s.run: %d chains left of %d at time %g\n",
                name.c_str(), int(chains.nChains()), int(nc), runTime.value()
            );
            return 1;
        }

        // Every bead in the slit, every step
        const List<vector>& x = chains.positions();
        label outside = 0;
        for (const vector& p : x)
        {
            const scalar z = p.z() - z0;
            if (z < 0 || z > h)
            {
                ++outside;
                worstOutside = max(worstOutside, max(-z, z - h));
            }
        }
        nOutside += outside;
        if (outside) ++nOutsideSteps;

        const label sampleStep = step - nEquilibration;
        if (sampleStep <= 0 || sampleStep % sampleEvery) continue;

        maxRodError = max(maxRodError, chains.maxRodLengthError());
        for (label c = 0; c < nc; ++c)
        {
            // A chain's samples in the block of its id: the cloud keeps
            // its chains in the order of their cells, which changes as
            // they move, so a chain's index is not the same chain's
            // from sample to sample (blocks of mixed chains would
            // understate the standard errors)
            const label block = chains.globalId(c);
            if (block < 0 || block >= nc)
            {
                FatalErrorInFunction
                    << "Chain id " << block << " outside 0.." << nc - 1
                    << exit(FatalError);
            }
            const label s = chains.start(c);
            auto binOf = [&](const label i)
            {
                const scalar z = (x[i].z() - z0)/h;
                return min(max(label(z*nBins), label(0)), nBins - 1);
            };
            const label b0 = binOf(s), b1 = binOf(s + N - 1);
            const label bi = binOf(s + kInner);
            const label bj = binOf(s + N - 1 - kInner);
            for (label b = 0; b < nBins; ++b)
            {
                endBins[b].add(block, 0.5*((b == b0) + (b == b1)));
                innerBins[b].add(block, 0.5*((b == bi) + (b == bj)));
            }
            rg2.add(block, chains.radiusOfGyrationSqr(c));

            auto inCentre = [&](const label i)
            {
                return mag(x[i].z() - z0 - 0.5*h) < centreHalf ? 1.0 : 0.0;
            };
            centre.add(block, 0.5*(inCentre(s) + inCentre(s + N - 1)));
        }
    }

    Info<< nl;
    cloud.writeReport(Info);
    Info<< "Rod error: largest at the samples " << maxRodError
        << " (rebounds move one bead of a rigid chain: the paper's"
        << " approximation; the next step's constraint restores the rods)"
        << nl << endl;

    std::printf
    (
        "%s %s.transferIntegral: K = %.6f (transfer integral), Monte Carlo"
        " %.6f +- %.2g, deviation %.2f SE (tolerance 4 SE); Casassa %.4f\n",
        std::abs(K - Kmc) <= 4*KmcSE ? "PASS" : "FAIL", name.c_str(),
        K, Kmc, KmcSE, (Kmc - K)/KmcSE, Kcasassa
    );
    if (std::abs(K - Kmc) > 4*KmcSE) ++nFailedChecks();

    std::printf
    (
        "%s %s.inside: %d bead-steps outside [0, h] in %d steps"
        " (worst %.3g); %d chains, none lost\n",
        nOutside == 0 ? "PASS" : "FAIL", name.c_str(), int(nOutside),
        int(nOutsideSteps), worstOutside, int(nc)
    );
    if (nOutside) ++nFailedChecks();

    // Initial end beads: Pearson's chi^2 of the nc independent samples
    // against the exact bins, chi^2 with nBins - 1 degrees of freedom; the
    // bound is its upper 1e-4 quantile (Wilson and Hilferty's cube-root
    // normal approximation, z = 3.719)
    {
        double chi2 = 0;
        const double n = nc;
        for (label b = 0; b < nBins; ++b)
        {
            chi2 += sqr(initialEnd[b] - n*endExact[b])/(n*endExact[b]);
        }
        const double k = nBins - 1;
        const double bound =
            k*std::pow(1 - 2/(9*k) + 3.719*std::sqrt(2/(9*k)), 3);
        const bool ok = chi2 < bound;
        std::printf
        (
            "%s %s.initialProfile: chi^2 %.2f of the %d initial end beads"
            " (one a chain) against the exact bins (%d bins; required"
            " < %.1f, the upper 1e-4 quantile of chi^2 with %d degrees of"
            " freedom)\n",
            ok ? "PASS" : "FAIL", name.c_str(), chi2, int(n), int(nBins),
            bound, int(k)
        );
        if (!ok) ++nFailedChecks();
    }

    double m, se;
    double chi2 = 0;
    for (label b = 0; b < nBins; ++b)
    {
        endBins[b].result(m, se);
        chi2 += sqr((m - endExact[b])/se);
        const double zLo = h*b/nBins, zHi = h*(b + 1)/nBins;
        char label[64];
        std::snprintf(label, sizeof(label), "P(%.3g<z<%.3g)", zLo, zHi);
        reportBin
        (
            checkProfile, name + ".endBead.bin" + std::to_string(b), label,
            m, se, endExact[b]
        );
    }
    for (label b = 0; b < nBins; ++b)
    {
        innerBins[b].result(m, se);
        chi2 += sqr((m - innerExact[b])/se);
        const double zLo = h*b/nBins, zHi = h*(b + 1)/nBins;
        char label[64];
        std::snprintf(label, sizeof(label), "P(%.3g<z<%.3g)", zLo, zHi);
        reportBin
        (
            checkProfile,
            name + ".bead" + std::to_string(kInner) + ".bin"
          + std::to_string(b), label, m, se, innerExact[b]
        );
    }
    rg2.result(m, se);
    const double Rg2 = a*a*(N*N - 1.0)/(6*N);
    Info<< "chi^2 of the " << 2*nBins << " bins (each histogram sums to 1:"
        << " about " << 2*(nBins - 1) << " degrees of freedom): " << chi2
        << nl << "<Rg^2> in the slit " << m << " +- " << se
        << " (free chain " << Rg2 << ")" << nl << endl;

    // Partition coefficient from the end beads' central density
    const std::string Kname = name + ".partitionCoefficient";
    centre.result(m, se);
    if (!hasCentre || m <= 0)
    {
        std::printf
        (
            "INFO %s: not measured: %s (slit seen %.4g, 2(N-1)a = %.4g);"
            " exact %.5f\n",
            Kname.c_str(),
            hasCentre ? "no end bead in the central region"
          : "no central region", hSeen, 2*(N - 1)*a, K
        );
    }
    else
    {
        const double Ksim = 2*centreHalf/(h*m);
        const double KsimSE = Ksim*se/m;
        std::printf
        (
            "INFO %s: K = %.5f +- %.2g (SE), exact %.5f, deviation %.1f SE",
            Kname.c_str(), Ksim, KsimSE, K, (Ksim - K)/KsimSE
        );
        if (levelSet)
        {
            std::printf
            (
                "; walls at the level set's zero (h - 2c = %.6g): exact"
                " %.5f, deviation %.1f SE",
                hSeen, Kseen, (Ksim - Kseen)/KsimSE
            );
        }
        std::printf("\n");
    }

    const double nSteps = nEquilibration + nSampling;
    std::printf
    (
        "INFO %s.cost: %.4g CPU ms per step, %.4g CPU us per bead-step"
        " (evolve only: %.0f steps of %d beads, %.2f s)\n",
        name.c_str(), 1e3*evolveSeconds/nSteps,
        1e6*evolveSeconds/(nSteps*nc*N), nSteps, int(nc*N), evolveSeconds
    );

    Info<< "End" << nl << endl;

    return nFailedChecks() ? 1 : 0;
}


// ************************************************************************* //
