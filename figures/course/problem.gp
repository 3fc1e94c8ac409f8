# The two-body contact problem of Ben Belgacem, Hild and Laborde (1998), section 2, in the
# course's geometry: body 1 above Gamma_c, body 2 below, nonmatching traces on Gamma_c.
# Regenerate with `gnuplot problem.gp` (writes problem.png and problem.pdf).

L  = 2.0     # length of Gamma_c
H1 = 1.0     # height of body 1
H2 = 0.8     # height of body 2
n1 = 5       # elements of body 1's trace xi^1 (non-mortar side)
n2 = 7       # elements of body 2's trace xi^2 (mortar side): nonmatching

unset border; unset tics; unset key
set size ratio -1
set xrange [-0.75 : L + 0.75]
set yrange [-H2 - 0.32 : H1 + 0.3]

# The bodies.
set object 1 rect from 0, 0 to L, H1  fc rgb "#dbe8f6" fs solid 1.0 border lc rgb "#1f4e79" lw 2
set object 2 rect from 0, -H2 to L, 0 fc rgb "#f6e3d3" fs solid 1.0 border lc rgb "#8a4b16" lw 2
# Gamma_u^l, held fixed: hatched strips outside the top of body 1 and the bottom of body 2.
set object 3 rect from 0, H1 to L, H1 + 0.08   fc rgb "#555555" fs pattern 4 border lc rgb "#555555"
set object 4 rect from 0, -H2 - 0.08 to L, -H2 fc rgb "#555555" fs pattern 4 border lc rgb "#555555"

# Gamma_c, and the nodes of the two traces on it.
set arrow 1 from 0, 0 to L, 0 nohead lw 4 lc rgb "#c00000" front
do for [i = 0 : n1] {
  set object 10 + i circle at i * L / n1, 0.045 size 0.025 fc rgb "#1f4e79" fs solid front
}
do for [k = 0 : n2] {
  set object 30 + k rect center k * L / n2, -0.045 size 0.045, 0.045 fc rgb "#8a4b16" fs solid front
}

# Outward normals on Gamma_c.
set arrow 2 from 0.22 * L, 0.0 to 0.22 * L, -0.3 head filled size 0.06, 20 lw 2 lc rgb "#1f4e79" front
set arrow 3 from 0.78 * L, 0.0 to 0.78 * L, 0.3 head filled size 0.06, 20 lw 2 lc rgb "#8a4b16" front

set label 1 "{/:Italic n}^1" at 0.22 * L + 0.05, -0.27 tc rgb "#1f4e79" front
set label 2 "{/:Italic n}^2" at 0.78 * L + 0.05, 0.27 tc rgb "#8a4b16" front

# Bodies, equations, boundary parts.
set label 3 "Ω^1"  at 0.5 * L, 0.45 * H1 center font ",22" front
set label 4 "Ω^2"  at 0.5 * L, -0.38 * H2 center font ",22" front
set label 5 "−div σ^1 = {/:Bold f}^1,  σ^1 = A^1 ε({/:Bold u}^1)"  at 0.5 * L, 0.75 * H1 center front
set label 6 "−div σ^2 = {/:Bold f}^2,  σ^2 = A^2 ε({/:Bold u}^2)"  at 0.5 * L, -0.72 * H2 center front
set label 7 "Γ_c" at L + 0.06, 0.0 left tc rgb "#c00000" font ",18" front
set label 8 "Γ@^1_u: {/:Bold u}^1 = 0" at 0.5 * L, H1 + 0.2 center front
set label 9 "Γ@^2_u: {/:Bold u}^2 = 0" at 0.5 * L, -H2 - 0.22 center front
set label 10 "Γ@^1_g" at -0.06, 0.5 * H1 right front
set label 11 "Γ@^1_g" at L + 0.06, 0.6 * H1 left front
set label 12 "Γ@^2_g" at -0.06, -0.5 * H2 right front
set label 13 "Γ@^2_g" at L + 0.06, -0.5 * H2 left front
set label 14 "σ^1{/:Bold n}^1 = {/:Bold g}^1" at L + 0.06, 0.42 * H1 left font ",10" front
set label 15 "σ^2{/:Bold n}^2 = {/:Bold g}^2" at L + 0.06, -0.68 * H2 left font ",10" front
set label 16 "ξ^1 (non-mortar)" at -0.06, 0.09 right tc rgb "#1f4e79" font ",10" front
set label 17 "ξ^2 (mortar)" at -0.06, -0.09 right tc rgb "#8a4b16" font ",10" front

set terminal pngcairo size 1000, 760 enhanced font "DejaVu Sans,13"
set output "problem.png"
plot NaN
set terminal pdfcairo size 6.6in, 5.0in enhanced font "DejaVu Sans,11"
set output "problem.pdf"
plot NaN
set output
