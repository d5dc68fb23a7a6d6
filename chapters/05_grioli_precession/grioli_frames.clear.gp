# Before a panel's arrows (grioli_frames.arrow.gp): the arrows and labels of the panel before it gone.
unset arrow
unset label
