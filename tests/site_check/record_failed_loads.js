// Runs before any script of the page: remembers every image or embedded object whose load
// failed, since a failed load can leave no other trace once the page has settled.
window.__siteCheckFailedLoads = [];
window.addEventListener('error', (event) => {
  const element = event.target;
  if (element instanceof HTMLImageElement) window.__siteCheckFailedLoads.push(element.src);
  if (element instanceof HTMLObjectElement) window.__siteCheckFailedLoads.push(element.data);
}, true);
