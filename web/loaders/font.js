// Text -> rings: a font parsed by opentype.js, the text laid out by it (kerning included), each
// glyph contour flattened so that no chord strays more than `tolerance` thousandths of an em
// from the curve. Output is in thousandths of an em, y up, baseline at y = 0.
import { parse } from '../vendor/opentype.min.mjs';
import { flattenQuad, flattenCubic, cleanRings } from '../geometry.js';

export function parseFont(buffer) {
  try {
    return parse(buffer);
  } catch (e) {
    // opentype.js throws plain Errors with terse messages ("Unsupported OpenType signature").
    throw new Error(`not a font opentype.js can read (TTF, OTF or WOFF; not WOFF2): ${e.message}`);
  }
}

// Glyph by glyph with pair kerning, not font.getPath(): opentype.js 2.0's substitution
// engine throws on lookups it does not support (TeX Gyre's 'ccmp' among them), and ligatures
// are no gain for a mesh.
// Characters the font has no glyph for (they would come out as its "missing" box) are left
// out; missingGlyphs() names them so the page can say so.
function layoutCommands(font, text, size) {
  const scale = size / font.unitsPerEm;
  const glyphs = Array.from(text).filter((ch) => !isMissing(font, ch)).map((ch) => font.charToGlyph(ch));
  const commands = [];
  let x = 0;
  glyphs.forEach((g, i) => {
    commands.push(...g.getPath(x, 0, size).commands);
    x += (g.advanceWidth || 0) * scale;
    if (i + 1 < glyphs.length) x += font.getKerningValue(g, glyphs[i + 1]) * scale;
  });
  return commands;
}

export function textToRings(font, text, tolerance) {
  const size = 1000;  // layout at 1000 units per em so the tolerance reads as 1/1000 em
  const rings = [];
  let ring = null, x = 0, y = 0;
  const close = () => {
    if (ring && ring.length) rings.push(ring);
    ring = null;
  };
  // opentype.js lays out y down; negate y for the mesher's y-up frame.
  for (const c of layoutCommands(font, text, size)) {
    switch (c.type) {
      case 'M':
        close();
        ring = [[c.x, -c.y]];
        break;
      case 'L':
        ring.push([c.x, -c.y]);
        break;
      case 'Q':
        flattenQuad(ring, x, -y, c.x1, -c.y1, c.x, -c.y, tolerance);
        break;
      case 'C':
        flattenCubic(ring, x, -y, c.x1, -c.y1, c.x2, -c.y2, c.x, -c.y, tolerance);
        break;
      case 'Z':
        close();
        break;
    }
    if (c.type !== 'Z') { x = c.x; y = c.y; }
  }
  close();
  return cleanRings(rings);
}

const isMissing = (font, ch) => /\S/u.test(ch) && font.charToGlyphIndex(ch) === 0;

// The distinct characters of `text` that `font` has no glyph for.
export function missingGlyphs(font, text) {
  return [...new Set(Array.from(text).filter((ch) => isMissing(font, ch)))];
}

export function fontName(font, fallback) {
  const n = font.names && (font.names.fullName || font.names.fontFamily);
  return (n && (n.en || Object.values(n)[0])) || fallback;
}
