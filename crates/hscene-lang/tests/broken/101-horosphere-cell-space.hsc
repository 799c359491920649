// The cells of {6,3,3} are inscribed in horospheres: no mirrored cell.
// expect: HSC0403
Globals { space = {6,3,3}; light_reach = 9; }
