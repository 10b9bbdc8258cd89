"""Going online with a valve: finding and selecting it, its status window, the upload, the Valve menu."""
