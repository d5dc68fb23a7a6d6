# What the scenes say about the linear stability of the Grioli precession they integrate
# (chapters/kit/stability.hpp): an error that an unstable precession grows is physics, and the
# report says so; a stable body's error is not called the instability's. Each case runs a scene
# with --json --no-figure and checks keys of its JSON report: a workbook_scene_case
# (cmake/Workbook.cmake) named "stability: <scene> <label>", labels `stability` and `scene`.
#
#   stability_case(<scene> <label> ARGS <arg>... EXPECT <key>=<regex>|<key><=<number>|<key>>=<number>...)
function(stability_case scene label)
  workbook_scene_case(${scene} ${label} KIND stability LABELS stability scene ${ARGN})
endfunction()

# A random body hung on a Grioli line whose precession is unstable (multiplier -1.22 a period):
# 100 periods grow its round-off by 1.22^100, and the report says that this, not the arithmetic,
# made its error.
set(unstable_body --Ag 1.2452 --Bg 3.0393 --Cg 3.9548 --mu 4.2875 --L 0.7461)
stability_case(grioli_body unstable-body ARGS ${unstable_body}
               EXPECT "precession_stability=^linearly unstable$" "floquet_multiplier=^-1\\.22"
                      "floquet_multiplier_rotation=^0\\.5" "error_dominated_by_instability=^ON$")
# The rule's other side: the same body over 5 periods (1.22^5 = 2.7) is unstable, but its error
# is not the instability's.
stability_case(grioli_body unstable-body-short-run ARGS ${unstable_body} --periods 5
               EXPECT "precession_stability=^linearly unstable$" "error_dominated_by_instability=^OFF$")
# The default body at L = 0.5 is stable; at L = 1 it lies in the large tongue (Chapter 7).
stability_case(grioli_body default-body EXPECT "precession_stability=^linearly stable$"
               "error_dominated_by_instability=^OFF$")
stability_case(grioli_body L-1 ARGS --L 1
               EXPECT "precession_stability=^linearly unstable$" "floquet_multiplier=^-1\\.25"
                      "error_dominated_by_instability=^ON$")
# Far out on the line (1e8 body sizes), where B and C agree to 16 digits: the monodromy on the
# gaps still finds the multipliers on the unit circle.
stability_case(grioli_body far-out ARGS --L 1.58e8
               EXPECT "precession_stability=^linearly stable$" "floquet_growth_per_period<=1e-4"
                      "floquet_growth_per_period>=1e-19")
# Chapter 5's benchmark on that body's moments at O: the headline's error is the instability's.
stability_case(grioli_integrators unstable-body ARGS --A 1.71777 --B 5.426 --C 5.86893 --f 31.3812 --repeats 1
               EXPECT "precession_stability=^linearly unstable$" "error_dominated_by_instability=^ON$")
# Chapter 7: the monodromy's multipliers agree with those of central differences of the full
# flow (a wrong Jacobian would not), in the most unstable shape of a small grid.
stability_case(grioli_stability variational-against-differences ARGS --nu 8 --nv 6 --periods 60
               EXPECT "error<=1e-5" "error>=1e-19" "tongue_multiplier_real=^-1\\.[0-9]")
