// Evaluated in a page after its load event; returns what the checker judges, as plain JSON.
(async () => {
  const pause = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
  const images = () => [...document.images];
  const objects = () => [...document.querySelectorAll('object[data]')];
  // The load event already waited for images; this only covers late additions. The wait ends as
  // soon as everything settled; its 20 s bound only matters on a machine busy with other tests
  // (5 s once let a 67 kB figure of chapter 08 be reported as broken) and stays below the 30 s
  // the checker gives this script.
  const settleSteps = 200;
  for (let i = 0; i < settleSteps && images().some((image) => !image.complete); ++i) {
    await pause(100);
  }
  // An embedded SVG's document can still be parsing on a busy machine: give it the same bound. A
  // figure that failed to load is recorded by record_failed_loads.js and is not waited for.
  const svgReady = (object) => object.contentDocument !== null &&
      object.contentDocument.documentElement !== null &&
      object.contentDocument.documentElement.localName === 'svg';
  const pending = () => objects().filter(
      (object) => !svgReady(object) && !(window.__siteCheckFailedLoads || []).includes(object.data));
  for (let i = 0; i < settleSteps && pending().length > 0; ++i) await pause(100);
  // Doxygen builds the visible tree from NAVTREE once the document is ready.
  const hasTree = typeof NAVTREE !== 'undefined';
  const treeShown = () => document.querySelector('#nav-tree-contents a') !== null;
  for (let i = 0; i < settleSteps && hasTree && !treeShown(); ++i) {
    await pause(100);
  }
  const failed = window.__siteCheckFailedLoads || [];
  const text = (element) => element.textContent.replace(/\s+/g, ' ').trim();
  return {
    url: location.href,
    title: document.title,
    images: images().map((image) => ({
      src: image.src,
      loaded: image.complete && image.naturalWidth > 0 && !failed.includes(image.src),
      naturalWidth: image.naturalWidth,
      inContents: image.closest('div.contents') !== null,
    })),
    // Doxygen embeds block-level SVG figures as <object>; a loaded one has a document.
    objects: objects().map((object) => ({
      src: object.data,
      type: object.type,
      loaded: !failed.includes(object.data) && svgReady(object),
      inContents: object.closest('div.contents') !== null,
    })),
    // Code listings: Doxygen highlights C++ in a fragment with keyword spans (span.keyword,
    // span.keywordtype, span.keywordflow); shell commands come out plain.
    fragments: [...document.querySelectorAll('div.contents div.fragment')].map((fragment) => ({
      cpp: fragment.querySelector('span[class^="keyword"]') !== null,
    })),
    links: [...document.querySelectorAll('a[href]')].map((link) => ({
      href: link.href,
      text: text(link),
      inNavTree: link.closest('#nav-tree') !== null,
      inContents: link.closest('div.contents') !== null,
    })),
    navTree: hasTree ? NAVTREE[0][2].map((entry) => ({title: entry[0], href: entry[1]})) : null,
    navTreeRoot: hasTree ? NAVTREE[0][1] : null,
  };
})()
