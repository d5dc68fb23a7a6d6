# A distance worth a mark: where B = C, or where A = C.
set arrow from @L@, graph 0 to @L@, graph 1 nohead ls @ls@
set label '@text@' at @L@, graph @height@ offset 0.5,0
