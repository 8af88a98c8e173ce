/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    quadrupoleTemperature

Description
    Semi-analytical temperature history of a 1-D soil made of layers of
    uniform gradient factor gamma over a uniform semi-infinite substrate,
    under an imposed surface temperature or surface flux history: the
    thermal quadrupoles of Krapez & Profice for graded media (§2.1, eqs.
    1-12; see doc/references.md) with the de Hoog,
    Knight & Stokes (1982) inversion of the Laplace transform. No mesh, no
    OpenFOAM case: OpenFOAM is used only to read the dictionary.

    Equations (z downward from the surface, T the rise above the uniform
    initial temperature, phi the flux downward, p the Laplace variable):

        c(z) dT/dt = d/dz (k(z) dT/dz)          linear conduction only
        b = sqrt(k c), a = k/c,  xi = int_0^z du/sqrt(a)
        T'' + 2 gamma T' - p T = 0 (' = d/dxi),  gamma = (1/(2c)) db/dz
                                                (paper eqs. 4, 5)
        layer of uniform gamma, thickness x in xi, alpha = sqrt(gamma^2 + p):
        (T, phi/b)_top = exp(gamma x) [[ch - (gamma/alpha) sh, sh/alpha],
                          [(p/alpha) sh, ch + (gamma/alpha) sh]] (T, phi/b)_bottom
                                                (paper eq. 10, ch = cosh(alpha x))
        substrate: phi = b_s sqrt(p) T at its top

    Eq. 10 is right as printed once phi/b is read with the local
    effusivity of each face (b_top on the left, b_bottom = b_top
    exp(2 gamma x) on the right); the layers are chained in (T, phi).
    The initial-condition terms (eqs. 8, 11) vanish for the rise above a
    uniform initial temperature, the only initial state supported.

    (derivation, units, the gamma -> 0 limit and the numerically safe form
    in src/quadrupoles/thermalQuadrupoles). The step and ramp responses of
    each output point are inverted (src/numerics/deHoogInversion) and
    superposed over the piecewise-linear surface history
    (src/quadrupoles/historyResponse: the convolution of the step
    response with the history, exact for a piecewise-linear history).
    The dictionary is read and checked by src/quadrupoles/quadrupoleInput,
    the table computed and written by src/quadrupoles/quadrupoleTable.

    Limits: 1-D, linear (properties independent of T), no phase change
    (no evaporation of the soil water, no latent heat), properties fixed
    in time, uniform initial temperature, a single condition at the
    surface (temperature or flux; no convective/radiative exchange), the
    soil below the layers semi-infinite and uniform.

    Dictionary: system/quadrupoleDict of the case (the current directory
    by default), or the file given by -dict. Annotated example:
    quadrupoleDict in this folder. Units SI: m, s, W, J, K (temperatures
    in C or K alike: only differences matter, the output is in the unit of
    initialTemperature and of the surface temperatures).

        initialTemperature  20;     // uniform initial temperature; default 0
                                    // (the output is then the rise)
        layers                      // top to bottom; may be empty
        {
            topSoil
            {
                thickness       0.1;        // m, > 0
                // at the top of the layer, either
                effusivity      879;        // b [W s^0.5/(m2 K)], > 0
                diffusivity     4.57e-7;    // a [m2/s], > 0
                // or
                // conductivity           0.6;    // k [W/(m K)], > 0
                // volumetricHeatCapacity 1.3e6;  // c = rho C [J/(m3 K)], > 0

                // the variation down the layer, exactly one of
                gamma           1.1e-3;     // [s^-0.5], any sign; 0: uniform
                // effusivityBottom 1200;   // b at the bottom [W s^0.5/(m2 K)]
                // conductivityBottom 1.0; volumetricHeatCapacityBottom 1.8e6;
                //                          // (gives b and a at the bottom)
                // diffusivityBottom 5e-7;  // a at the bottom [m2/s]; default
                //                          // = diffusivity (uniform a); not
                //                          // with the conductivityBottom form
            }
            // more layers...
        }
        substrate                   // below the layers, semi-infinite, uniform
        {
            effusivity      2008;   // or conductivity and
            diffusivity     5.96e-7;// volumetricHeatCapacity
        }
        surface
        {
            condition   temperature;    // temperature | flux
            // history: (time value) rows, either inline or in a file
            table       ((0 20) (600 700) (21600 700) (30000 100));
            // file     "fire.csv";     // relative to the case directory;
            //                          // columns time, value (others
            //                          // ignored) in the common table
            //                          // format (README "Numeric table
            //                          // files"); times must not decrease
            // timeUnit s;              // s | min | h: unit of the history
            //                          // times (default s)
        }
        depths          (0.01 0.02 0.05);   // m, > 0 (may be in the substrate)
        // output times [s], either
        endTime         86400;      // > 0
        writeInterval   600;        // [1e-7, 1] x endTime: writeInterval,
                                    // 2 writeInterval, ..., and endTime
        // or
        // times        (60 120 3600);  // increasing, > 0
        // outputFile   "postProcessing/quadrupoleTemperature/temperature.csv";
        //                          // default; relative to the case directory
        inversion                   // optional: the de Hoog parameters
        {
            M           30;         // 2M+1 evaluations of the transform per
                                    // series, [2, 500] (default 30)
            tolerance   1e-12;      // aimed relative discretisation error,
                                    // (0, 1e-3]; sets the abscissa
                                    // -ln(tolerance)/(2T) (default 1e-12)
            Tfactor     1;          // half period T = Tfactor x the largest
                                    // time of each decade, [0.5, 10]
                                    // (default 1)
        }

    Layer model: the effusivity varies as b_top exp(2 gamma xi) and the
    diffusivity linearly in z from its top to its bottom value, hence
    c = b/sqrt(a) and k = b sqrt(a) at every depth; gamma 0 and equal
    diffusivities is the classical uniform layer. Given effusivityBottom
    (or conductivityBottom and volumetricHeatCapacityBottom) instead of
    gamma, gamma = ln(b_bottom/b_top)/(2 xi_L), xi_L the root diffusion
    time of the layer: the layer then has the given properties at both
    faces. To approximate a continuous profile (e.g. a water content
    rising with depth), split it into layers and give each its top and
    bottom values (Krapez & Profice report 0.1 K RMS on the surface
    temperature of their soil with two uniform-gamma layers, where 15
    uniform layers are needed: reproduced in tests/gradedSoilQuadrupole,
    0.084 K with layers exact in capacity and resistance, 0.21-0.52 K
    with face values).

    Surface history: theta(t) = 0 at t <= 0; the first row's value on
    (0, t_0]; linear between rows; the last value held after the last row;
    two rows with the same time make a jump. For condition temperature
    the values are temperatures (rise = value - initialTemperature), for
    flux they are the heat flux into the soil [W/m2] (positive heats).

    Output: a CSV file, one row per output time:
        time_s,T_surface,T_<depth>m,...
    temperatures = initialTemperature + rise (12 significant digits), the
    surface first (under an imposed temperature it is the history itself),
    then the depths in the order given. At the time of a jump of the
    history the value before the jump is written. The layers (properties
    at their faces), the history and the inversion are printed.

    Accuracy: the inversion is good to about 1e-11 of the response
    (tests/deHoogInversion, tests/quadrupoleExact); the superposition over
    a history multiplies this by about (output time)/(shortest history
    interval). Cost: about 2 us per distinct (output time - history time)
    and output point; the arguments recur with uniform steps and are
    computed once: 2000 output times x 2000 history rows x 7 points took
    4 s of CPU with uniform steps, 46 s when no argument recurs.

Usage
    quadrupoleTemperature [-case dir] [-dict file]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "quadrupoleTable.H"
#include <chrono>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    using namespace Foam;

    argList::addNote
    (
        "Temperature history at given depths of a 1-D soil of layers of"
        " uniform gradient factor gamma over a semi-infinite substrate,"
        " under an imposed surface temperature or flux history: thermal"
        " quadrupoles (Krapez & Profice) and de Hoog Laplace inversion"
        " (system/quadrupoleDict; no mesh)"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addOption
    (
        "dict",
        "file",
        "Read this dictionary instead of system/quadrupoleDict"
        " (relative to the case directory)"
    );

    #include "setRootCase.H"

    const auto wallStart = std::chrono::steady_clock::now();

    fileName dictFile(args.getOrDefault<fileName>("dict", "system/quadrupoleDict"));
    dictFile.expand();
    if (!dictFile.isAbsolute())
    {
        dictFile = args.path()/dictFile;
    }

    // Read and check everything, then print what was read
    const quadrupoleInput input(dictFile, args.path());
    input.report();

    // Solve and write
    const quadrupoleTable table(input);
    table.write(input.outputFile());

    const double wall =
        std::chrono::duration<double>
        (
            std::chrono::steady_clock::now() - wallStart
        ).count();

    Info<< "Wrote " << input.outputFile() << nl
        << "    " << table.nPairs() << " (time, history event) pairs, "
        << quadrupoleInput::sig(wall, 3).c_str() << " s" << nl;

    Info<< "\nEnd\n" << endl;

    return 0;
}


// ************************************************************************* //
