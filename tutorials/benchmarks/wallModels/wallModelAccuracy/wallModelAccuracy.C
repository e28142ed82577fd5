/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    wallModelAccuracy (tutorials/benchmarks/wallModels)

Description
    Accuracy against cost of the bead-wall models meshFaces and levelSet on
    a wall whose true geometry is known analytically:

    - plane: the inclined top wall z = z0 + s x of a blockMesh channel
      (planeCase; every other patch is an open 'patch');
    - pipe:  the curved wall x^2 + y^2 = R^2 of a blockMesh O-grid pipe
      along z (pipeCase; its faces are chords of the circle).

    nPaths random straight bead paths x + v t, t in (0, 1], are constructed
    (as tests/unit wallTest.C does): an impact point P on the true wall away
    from the open patches, a direction u into the wall (u.n >= 0.1, n the
    outward normal), a start x = P - l u inside the mesh (l in [0.2, 1.5],
    at least 0.15 from the wall) and v = u l / t* with t* uniform in
    [0.3, 0.9]. The exact impact of a model is where the path meets the
    true wall (meshFaces) or the true wall offset by the clearance
    (levelSet: its zero is the distance to the walls less the clearance).

    Per model: paths with no impact predicted (missed), the impact-position
    error |x + t v - P_exact| (RMS, median, 95th percentile, largest), the
    normal's error |n - n_exact| (RMS, largest), the CPU time of
    construction and the CPU time per predict() call (all paths, passes
    repeated until 0.3 s).

    Prints one line per model:
    RESULT geometry h model nPaths missed rms median p95 max nRms nMax
           setupCpu cpuPerCall[us]

Usage
    wallModelAccuracy -case <case> -geometry plane|pipe -h <cell size>
        [-nPaths 20000] [-clearanceFraction 0.02] [-nSamples 4] [-seed 1]
        (plane: -slope 0.25 -z0 2 -length 8 -width 6;
         pipe:  -radius 2 -length 8)

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "fvMesh.H"
#include "IStringStream.H"
#include "wallModel.H"
#include <random>
#include <vector>
#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>

using namespace Foam;
using namespace Foam::polymer;

namespace
{

struct path
{
    point x;
    vector v;
    point P;        // impact on the true wall
    vector u;       // unit direction
};

vector randomDirection(std::mt19937_64& gen)
{
    std::uniform_real_distribution<double> uniform(-1, 1);
    std::uniform_real_distribution<double> angle(0, 2*M_PI);
    const double c = uniform(gen);
    const double s = std::sqrt(1 - c*c);
    const double phi = angle(gen);
    return vector(s*std::cos(phi), s*std::sin(phi), c);
}

double cpuNow()
{
    return double(std::clock())/CLOCKS_PER_SEC;
}

double quantile(std::vector<double> e, const double q)
{
    if (e.empty()) return 0;
    std::sort(e.begin(), e.end());
    const size_t i = std::min(e.size() - 1, size_t(q*(e.size() - 1) + 0.5));
    return e[i];
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::addOption("geometry", "word", "plane | pipe");
    argList::addOption("h", "scalar", "cell size (for the clearance)");
    argList::addOption("nPaths", "label", "random paths (20000)");
    argList::addOption("clearanceFraction", "scalar", "clearance / h (0.02)");
    argList::addOption("nSamples", "label", "levelSet samples (4)");
    argList::addOption("seed", "label", "seed (1)");
    argList::addOption("slope", "scalar", "plane: dz/dx of the top wall");
    argList::addOption("z0", "scalar", "plane: height of the top wall at x=0");
    argList::addOption("length", "scalar", "plane: x extent; pipe: z extent");
    argList::addOption("width", "scalar", "plane: y extent");
    argList::addOption("radius", "scalar", "pipe: radius");

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

    const word geometry = args.get<word>("geometry");
    const scalar h = args.get<scalar>("h");
    const label nPaths = args.getOrDefault<label>("nPaths", 20000);
    const scalar c = h*args.getOrDefault<scalar>("clearanceFraction", 0.02);
    const label nSamples = args.getOrDefault<label>("nSamples", 4);
    const label seed = args.getOrDefault<label>("seed", 1);
    const scalar slope = args.getOrDefault<scalar>("slope", 0.25);
    const scalar z0 = args.getOrDefault<scalar>("z0", 2);
    const scalar L = args.getOrDefault<scalar>("length", 8);
    const scalar W = args.getOrDefault<scalar>("width", 6);
    const scalar R = args.getOrDefault<scalar>("radius", 2);
    const bool isPlane = (geometry == "plane");
    if (!isPlane && geometry != "pipe")
    {
        FatalErrorInFunction << "geometry plane or pipe" << exit(FatalError);
    }

    // Outward unit normal of the true wall at a point on it
    const vector planeNormal = vector(-slope, 0, 1)/std::sqrt(1 + slope*slope);
    auto wallNormal = [&](const point& p) -> vector
    {
        if (isPlane) return planeNormal;
        vector r(p.x(), p.y(), 0);
        return r/mag(r);
    };
    // Distance of a point inside from the true wall
    auto wallDistance = [&](const point& p) -> scalar
    {
        if (isPlane) return (z0 + slope*p.x() - p.z())/std::sqrt(1 + slope*slope);
        return R - std::sqrt(sqr(p.x()) + sqr(p.y()));
    };
    // Where x + s u (s >= 0) first meets the true wall offset inward by d
    auto exactHit = [&](const point& x, const vector& u, const scalar d) -> point
    {
        if (isPlane)
        {
            // n.(x + s u) = n.Pwall - d, n.Pwall = z0/sqrt(1+s^2)
            const scalar nP = z0/std::sqrt(1 + slope*slope) - d;
            const scalar s = (nP - (planeNormal & x))/(planeNormal & u);
            return x + s*u;
        }
        // (x + s u)_xy^2 = (R - d)^2
        const scalar a = sqr(u.x()) + sqr(u.y());
        const scalar b = 2*(x.x()*u.x() + x.y()*u.y());
        const scalar cc = sqr(x.x()) + sqr(x.y()) - sqr(R - d);
        const scalar s = (-b + std::sqrt(b*b - 4*a*cc))/(2*a);
        return x + s*u;
    };

    // Paths
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> uniform(0, 1);
    const scalar margin = 1.5;
    std::vector<path> paths;
    paths.reserve(nPaths);
    label tries = 0;
    while (label(paths.size()) < nPaths && tries < 100*nPaths)
    {
        ++tries;
        point P;
        if (isPlane)
        {
            const scalar x = margin + (L - 2*margin)*uniform(gen);
            const scalar y = margin + (W - 2*margin)*uniform(gen);
            P = point(x, y, z0 + slope*x);
        }
        else
        {
            const scalar phi = 2*M_PI*uniform(gen);
            const scalar z = margin + (L - 2*margin)*uniform(gen);
            P = point(R*std::cos(phi), R*std::sin(phi), z);
        }
        const vector n = wallNormal(P);
        const vector u = randomDirection(gen);
        if ((u & n) < 0.1) continue;
        const scalar l = 0.2 + 1.3*uniform(gen);
        const point x = P - l*u;
        if (wallDistance(x) < 0.15) continue;
        if (isPlane && (x.z() < 0.05 || x.x() < 0.05 || x.x() > L - 0.05
            || x.y() < 0.05 || x.y() > W - 0.05)) continue;
        if (!isPlane && (x.z() < 0.05 || x.z() > L - 0.05)) continue;
        if (mesh.findCell(x) < 0) continue;
        const scalar tStar = 0.3 + 0.6*uniform(gen);
        paths.push_back({x, u*l/tStar, P, u});
    }
    Info<< "Paths: " << paths.size() << " (" << tries << " tries), clearance "
        << c << nl << endl;

    const word models[] = {"meshFaces", "levelSet"};
    for (const word& model : models)
    {
        const bool isLevelSet = (model == "levelSet");
        OStringStream os;
        os  << "wall " << model << ";\n";
        if (isLevelSet)
        {
            os  << "levelSetCoeffs { clearance " << c << "; nSamples "
                << nSamples << "; }\n";
        }
        IStringStream is(os.str());
        const dictionary subModels(is);

        const double setup0 = cpuNow();
        autoPtr<wallModel> wall = wallModel::New(subModels, mesh);
        const double setupCpu = cpuNow() - setup0;
        const label wallPatch = mesh.boundaryMesh().findPatchID("walls");

        // Accuracy
        label missed = 0, wrongPatch = 0;
        std::vector<double> err, nerr;
        double worst = -1;
        std::string worstText;
        err.reserve(paths.size());
        for (const path& p : paths)
        {
            wallModel::impact hit;
            if (!wall->predict(p.x, p.v, 1, hit))
            {
                ++missed;
                continue;
            }
            if (hit.patch != wallPatch) ++wrongPatch;
            const point exact =
                isLevelSet ? exactHit(p.x, p.u, c) : p.P;
            const point predicted = p.x + hit.time*p.v;
            err.push_back(mag(predicted - exact));
            if (err.back() > worst)
            {
                worst = err.back();
                worstText = "x " + name(p.x) + " v " + name(p.v)
                    + " predicted " + name(predicted) + " exact "
                    + name(exact) + " n " + name(hit.normal);
            }
            nerr.push_back(mag(hit.normal + wallNormal(p.P)));  // into fluid
        }
        double sum2 = 0, nsum2 = 0, emax = 0, nmax = 0;
        for (size_t i = 0; i < err.size(); ++i)
        {
            sum2 += err[i]*err[i];
            nsum2 += nerr[i]*nerr[i];
            emax = std::max(emax, err[i]);
            nmax = std::max(nmax, nerr[i]);
        }
        const double nn = std::max<size_t>(err.size(), 1);

        // Cost: passes over all paths until 0.3 s of CPU time
        label calls = 0, hits = 0;
        const double t0 = cpuNow();
        double t1 = t0;
        do
        {
            for (const path& p : paths)
            {
                wallModel::impact hit;
                hits += wall->predict(p.x, p.v, 1, hit);
                ++calls;
            }
            t1 = cpuNow();
        } while (t1 - t0 < 0.3);
        const double perCall = 1e6*(t1 - t0)/calls;

        Info<< model << ": " << missed << " missed, " << wrongPatch
            << " on another patch, " << calls << " timed calls" << nl
            << "    largest position error " << worst << ": " << worstText.c_str()
            << endl;
        std::printf
        (
            "RESULT %s %g %s %d %d %.6e %.6e %.6e %.6e %.6e %.6e %.4f %.4f %d\n",
            geometry.c_str(), h, model.c_str(), int(paths.size()), int(missed),
            std::sqrt(sum2/nn), quantile(err, 0.5), quantile(err, 0.95), emax,
            std::sqrt(nsum2/nn), nmax, setupCpu, perCall, int(mesh.nCells())
        );
        std::fflush(stdout);
    }

    Info<< "End" << nl << endl;
    return 0;
}
