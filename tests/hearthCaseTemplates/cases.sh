# Sourced by tests/hearthCaseTemplates/run and
# tests/hearthCaseTemplatesPendular/run after testFunctions (see run)
here="$testsDir/hearthCaseTemplates"
cd "$scratch" || exit 1
hc="$topDir/bin/hearthCase"

# one NAME SOLVER RANKS GEOMETRY: write, run and check one case
one()
{
    local name="$1" solver="$2" ranks="$3" geometry="$4"
    mkdir -p "$name"
    sed -e "s/GEOMETRY/$geometry/" -e "s/SOLVER/$solver/" \
        -e "s/RANKS/$ranks/" "$here/hearthCaseDict" > "$name/hearthCaseDict"
    (cd "$name" && "$hc" case > log.hearthCase 2>&1) \
        || { fail "$name" "hearthCase: $(tail -2 $name/log.hearthCase)"; return; }
    if ! runTimed 300 "$name/log.Allrun" "$name/case/Allrun"
    then
        fail "$name" "Allrun: $(tail -3 $name/log.Allrun)"
        return
    fi
    python3 "$here/check.py" "$name/case" > "$name/log.check" 2>&1 \
        && pass "$name" "$(tail -1 $name/log.check)" \
        || fail "$name" "$(grep -v '^ok' $name/log.check | head -5)"
}

w='rFire 20 cm; refinement 0.5;'
b='rBasin 20 cm; dBasin 8 cm; refinement 0.5;'
# SOLVERS (default ahcFoam): tests/hearthCaseTemplatesPendular runs this
# script with pendularFoam, serial (2 ranks of pendularFoam on the loaded
# 2-core machine took 8 times its CPU time in wall time)
ranks=2
[ "${SOLVERS:-ahcFoam}" = pendularFoam ] && ranks=1
for s in ${SOLVERS:-ahcFoam}
do
    one "$s.flatDiscWedge"   $s $ranks "template flatDiscWedge; $w"
    one "$s.circularBasin"   $s $ranks "template circularBasin; $b"
    one "$s.flatDisc3D"      $s 1 "template flatDisc3D; refinement 0.25;"
    one "$s.circularBasin3D" $s 1 "template circularBasin3D; refinement 0.25;"
    one "$s.pitQuarter"      $s 1 "template rectangularPit; refinement 0.25;"
    one "$s.pitFull"         $s 1 "template rectangularPit; refinement 0.25; symmetry full; splitWalls no;"
done
summary
