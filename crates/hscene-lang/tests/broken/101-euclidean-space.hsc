// A symbol of no hyperbolic honeycomb, and a light reach too far.
// expect: HSC0313 HSC0403
Globals { space = {4,3,4}; light_reach = 9; }
