# One power p's pair of curves in level_escape.svg (@curves@ in level_transitions.escape.gp).
'-' with points ls @ls@ pt 7 ps 1.2 title 'p = @p@, (6.1) integrated', '-' with lines ls @ls@ dt 2 title 'p = @p@, averaged equation'
