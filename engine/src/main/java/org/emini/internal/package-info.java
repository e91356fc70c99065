/** What the engine's packages share and users do not need: argument checks. Not part of the API. */
package org.emini.internal;
