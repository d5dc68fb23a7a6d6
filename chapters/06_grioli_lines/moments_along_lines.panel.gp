set title @title@
unset arrow
unset label
