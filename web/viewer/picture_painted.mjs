// Calls `then(paintedMs)` once `picture` (an <img> with an elementtiming attribute) has been painted:
// paintedMs is when, in milliseconds since the page's navigation started, as the browser reports it
// (Element Timing), or null where the browser does not say (then two frames after the picture loaded).
// At once, with null, when there is no picture or it cannot load.
export function whenPictureIsPainted(picture, then) {
  let called = false;
  const once = (paintedMs) => {
    if (!called) then(paintedMs);
    called = true;
  };
  if (!picture) return once(null);
  picture.addEventListener('error', () => once(null));
  if (PerformanceObserver.supportedEntryTypes?.includes('element')) {
    new PerformanceObserver((list, observer) => {
      const painted = list.getEntries().find((entry) => entry.identifier === picture.getAttribute('elementtiming'));
      if (!painted) return;
      observer.disconnect();
      once(painted.renderTime > 0 ? painted.renderTime : null);
    }).observe({ type: 'element', buffered: true });
    return;
  }
  const afterTwoFrames = () => requestAnimationFrame(() => requestAnimationFrame(() => once(null)));
  if (picture.complete) afterTwoFrames();
  else picture.addEventListener('load', afterTwoFrames);
}
