// A site page's first script (cadnurbs-assets/site_start.js, loaded before the viewer's): starts the mesh
// worker on the page's part at once, so that the module compiles and the part is read while the browser
// loads the viewer's larger script. The viewer's startSiteViewer takes the worker from
// window.cadnurbsMeshWorker, the one name the two scripts share.
import { sitePagePart, startMeshWorker } from './mesh_worker_start.mjs';

window.cadnurbsMeshWorker = startMeshWorker(sitePagePart());
