// a few bytes of text asking for gigabytes: the third tessellation passes the primitive cap and is refused before it is built
// expect: HSC0601
BRDFs   { stone: diffuse = (0.7, 0.7, 0.7); }
Lights  { (0, 0, 0.3), (1, 1, 1), (1, 1, 1); }
Objects {
  Tessellation435 7, #stone;
  Tessellation435 7, #stone;
  Tessellation435 7, #stone;
  Tessellation435 7, #stone;
  Tessellation435 7, #stone;
  Tessellation435 7, #stone;
  Tessellation435 7, #stone;
  Tessellation435 7, #stone;
  Tessellation435 7, #stone;
  Tessellation435 7, #stone;
}
