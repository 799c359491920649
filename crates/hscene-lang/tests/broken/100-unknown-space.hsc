// A space hscene does not know: the message lists the ones it does.
// expect: HSC0403
Globals { space = poincare_sphere; }
