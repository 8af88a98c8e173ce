/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "casePaths.H"
#include "OSspecific.H"

#include <climits>
#include <cstdlib>
#include <string>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

Foam::fileName Foam::casePaths::canonical(const fileName& path)
{
    fileName p(path);
    p.expand();
    if (!p.isAbsolute())
    {
        p = cwd()/p;
    }
    p.clean();

    // Resolve the longest existing prefix; keep the rest as it is
    std::string head(p);
    std::string tail;
    while (true)
    {
        char buf[PATH_MAX];
        if (::realpath(head.c_str(), buf))
        {
            fileName result(std::string(buf) + tail);
            result.clean();
            return result;
        }
        const auto slash = head.rfind('/');
        if (slash == std::string::npos || slash == 0)
        {
            return p;
        }
        tail = head.substr(slash) + tail;
        head.erase(slash);
    }
}


bool Foam::casePaths::inside(const fileName& path, const fileName& dir)
{
    const std::string p(canonical(path));
    const std::string d(canonical(dir));
    return p == d || (p.size() > d.size() && p.compare(0, d.size(), d) == 0
        && (d == "/" || p[d.size()] == '/'));
}


Foam::fileName Foam::casePaths::copiedDirHolding
(
    const fileName& casePath,
    const word& startName,
    const fileName& target
)
{
    for (const word& sub : {word("system"), word("constant"), startName})
    {
        if (inside(target, casePath/sub))
        {
            return casePath/sub;
        }
    }
    return fileName();
}

// ************************************************************************* //
