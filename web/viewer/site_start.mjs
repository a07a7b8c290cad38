// A site page's one script (cadnurbs-assets/site_start.js; the page names its part in this script
// element's data-name and data-part). The page's picture of the part is its first frame, so nothing else
// competes with the browser for it: once the picture is painted, this starts the mesh worker on the part
// and loads the viewer (viewer.js, beside this script with the other shared files), which takes over.
import { startMeshWorker } from './mesh_worker_start.mjs';
import { whenPictureIsPainted } from './picture_painted.mjs';

// The page's part: its name and .cnb (`names`: data-name, and data-part, the .cnb's URL relative to the
// page) and the URLs of the shared files in the folder `assets` (an absolute URL).
function sitePagePart(names, assets) {
  return { name: names.name, partUrl: new URL(names.part, document.baseURI).href, wasmUrl: `${assets}cadnurbs_wasm.wasm`,
           workerUrl: `${assets}mesh_worker.js`, rendererUrl: `${assets}render_worker.js`, viewerUrl: `${assets}viewer.js` };
}

const script = document.currentScript;
const part = sitePagePart(script.dataset, new URL('.', script.src).href);
const picture = document.getElementById('cadnurbs-picture');
whenPictureIsPainted(picture, () => {
  const meshWorker = startMeshWorker(part);
  const viewer = document.createElement('script');
  viewer.src = part.viewerUrl;
  viewer.onload = () => cadnurbsViewer.startSiteViewer({ meshWorker, part, picture });
  document.head.appendChild(viewer);
});
