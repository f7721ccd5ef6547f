// The status line after a run: in words, whether the run met what was asked and, when it did
// not, what it reached. It goes by the mesher's status ('ok' or anything else), so a status
// this page does not know yet is still said plainly, with the mesher's message.
import { AUTO, boundSentence, truncateDeg } from './max-angle.js';

const NAMES = { acute: 'acute', nonobtuse: 'non-obtuse' };

// r: the page's result record (mode, certified, targetMet, minAngle, maxAngle, askedMaxAngle,
// angleBound, angleFloor, smallestDomainAngle, milliseconds, options); m: { status, message }
// as the mesher returned them; warnings: the mesher's stats.warnings.
// Returns { text, kind } with kind '' (met), 'warn' (a mesh, but not the one asked for) or
// 'error' (no mesh).
export function verdict(r, m, warnings = []) {
  const status = m.status ?? (r.targetMet === false ? 'target-not-met' : 'ok');
  const time = `Meshed in ${formatMs(r.milliseconds)}`;
  const notes = warnings.length ? `\n${warnings.slice(0, 3).join('\n')}` : '';
  // An empty mesh is never a success, whatever the status: say why (the mesher's words).
  if (!(r.triangles > 0)) {
    const why = [m.message, ...warnings].filter(Boolean);
    return { text: `${time}: no triangles${status === 'ok' ? '' : ` (status '${status}')`}: ${why.join('; ') || 'the domain is empty'}.`, kind: 'error' };
  }
  if (status === 'ok' && r.targetMet !== false) return { text: `${time}: ${met(r)}${notes}`, kind: '' };
  // Cancelled while spending more time: the best mesh found, which meets the target.
  if (status === 'cancelled' && r.targetMet === true)
    return { text: `${time}: the search for fewer points was cancelled; the best mesh it found is shown, ${uncapitalise(met(r))}${notes}`, kind: '' };
  return { text: `${time}: ${missed(r, m, status)}${notes}`, kind: 'warn' };
}

// The sizes' verdict (stats.sizeRatio: the largest longest-edge / size over the triangles,
// areas counted as the edge of a square of that area) for the stats: met, or missed by the
// worst ratio, rounded up so that a miss never reads as 1.00.
export function sizeWords(ratio) {
  return ratio <= 1 ? `met (${down2(ratio)})` : `missed (${up2(ratio)})`;
}

// The same in the status line's words.
function sizeSentence(r) {
  if (r.sizeRatio == null) return '';
  const o = r.options || {};
  if (r.sizeRatio > 1) {
    return `Sizes missed: ratio ${up2(r.sizeRatio)} (the worst triangle's size over the one asked for; 1 or less is met).`;
  }
  const what = [o.maxEdge > 0 && `every edge at most ${o.maxEdge}`, r.regionAreas && 'every region\'s area bound'].filter(Boolean);
  return `Sizes met${what.length ? `: ${what.join(', ')}` : ''} (ratio ${down2(r.sizeRatio)}).`;
}

const down2 = (v) => (Math.trunc(v * 100) / 100).toFixed(2);
const up2 = (v) => (Math.ceil(v * 100) / 100).toFixed(2);

// The one time figure of a run, as the stats' Time row shows it.
export function formatMs(ms) {
  if (!Number.isFinite(ms)) return '–';
  return `${ms < 10 ? Number(ms.toFixed(1)) : Math.round(ms).toLocaleString('en')} ms`;
}

function met(r) {
  const o = r.options || {};
  const parts = [];
  if (NAMES[r.mode]) parts.push(`certified ${NAMES[r.mode]}.`);
  else if (r.mode === 'quality') parts.push('quality target met.');
  else parts.push('constrained Delaunay triangulation.');
  const sentence = boundSentence(r);
  if (sentence) parts.push(sentence);
  if (o.minAngle > 0 && r.mode !== 'cdt') {
    // Corners of the input smaller than the minimum asked for cannot hold it; the mesher
    // keeps them as they are, so "met" means met everywhere else.
    const corner = r.smallestDomainAngle;
    parts.push(corner != null && corner < o.minAngle
      ? `Every angle at least ${o.minAngle}° except in the input's corners below it (the smallest is ${deg(corner)}), which no mesh can change.`
      : `Every angle at least ${o.minAngle}° (smallest ${truncateDeg(r.minAngle, 2)}).`);
  }
  if (o.maxArea > 0 && r.mode !== 'cdt') parts.push(`Every triangle's area at most ${o.maxArea}.`);
  const sizes = sizeSentence(r);
  if (sizes) parts.push(sizes);
  return capitalise(parts.join(' '));
}

function missed(r, m, status) {
  const reason = m.message ? ` (${m.message})` : '';
  const head = status === 'target-not-met' ? 'Target not met' : `Not met (status '${status}')`;
  // Acute with a bound below 90: the bound sentence says what was asked and reached.
  const bounded = r.mode === 'acute' && r.askedMaxAngle !== AUTO && r.askedMaxAngle != null && r.askedMaxAngle < 90;
  const parts = [];
  if (bounded && r.certified) {
    parts.push(`${head}: ${uncapitalise(boundSentence(r))} The mesh is certified acute.`);
  } else if (NAMES[r.mode] && !r.certified) {
    parts.push(`${head}: not certified ${NAMES[r.mode]}${reason}. The best mesh so far is shown; its largest angle is ${angle(r.maxAngle)}.`);
  } else {
    parts.push(`${head}${reason}.`);
    if (NAMES[r.mode]) parts.push(`The mesh is certified ${NAMES[r.mode]}.`);
    if (r.mode === 'acute' && r.askedMaxAngle === AUTO) parts.push(boundSentence(r));
  }
  const o = r.options || {};
  if (o.minAngle > 0 || r.mode === 'quality') parts.push(`The smallest angle reached is ${angle(r.minAngle, 2)}${o.minAngle > 0 ? ` (asked: ${o.minAngle}°)` : ''}.`);
  const sizes = sizeSentence(r);
  if (sizes) parts.push(sizes);
  return parts.join(' ');
}

const deg = (v) => `${Number(v.toFixed(2))}°`;
const angle = (v, digits = 3) => (v == null ? 'unknown' : truncateDeg(v, digits));
const capitalise = (s) => s.charAt(0).toUpperCase() + s.slice(1);
const uncapitalise = (s) => s.charAt(0).toLowerCase() + s.slice(1);
