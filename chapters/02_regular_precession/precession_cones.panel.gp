# One case: the space cone's rays and rim, the body cone's rays and rim at t*, the path of a
# body point, and the contact ray Ω(t*).
set title @title@
splot '-' with lines ls 8 lw 0.8, '-' with lines ls 1 lw 2, '-' with lines ls 6 lw 0.8, '-' with lines ls 2 lw 2, '-' with lines ls 3 lw 1, '-' with lines ls 7 lw 3
