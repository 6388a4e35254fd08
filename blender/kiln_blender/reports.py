"""Collecting what the exporter could not map, as one message per kind of problem."""


class Reports:
    """Things the exporter could not map, grouped by kind.

    ``add(kind, item)`` records that ``item`` (a material, object or light name) has the
    problem ``kind``; every kind has a message template (``KINDS``). ``messages()`` gives one
    line per kind, in the order the kinds were first seen, naming how many distinct items
    have it and up to five of them.
    """

    KINDS = {
        "material-nodes": "{n} material(s) use nodes other than a Principled BSDF: exported as "
                          "diffuse with the viewport colour ({items})",
        "principled-input": "{n} material(s) have Principled settings the exporter ignores "
                            "(subsurface, sheen or anisotropy above 0, alpha below 1, "
                            "emission, or a linked input other than Base Color) ({items})",
        "base-color-nodes": "{n} material(s) have a Base Color linked to nodes other than an "
                            "Image Texture: exported with the socket's own colour ({items})",
        "metal-texture": "{n} metallic material(s) have a textured Base Color: exported as the "
                         "named metal without the texture ({items})",
        "image-mapping": "{n} image texture(s) have a linked Vector input: exported with the "
                         "mesh's active UV map ({items})",
        "image-missing": "{n} image(s) could not be written (missing file, or a sequence, "
                         "movie or tiled image): left out ({items})",
        "attribute-missing": "{n} mesh(es) lack the float point attribute their ATTRIBUTE "
                             "temperature source names: not hot ({items})",
        "object-type": "{n} object(s) of a type the exporter does not write (volume, point "
                       "cloud, grease pencil, ...): left out ({items})",
        "camera-type": "{n} camera(s) are panoramic: exported as perspective ({items})",
        "light-nodes": "{n} light(s) use nodes or a texture: exported with the colour and "
                       "power only ({items})",
        "area-spread": "{n} area light(s) have a Spread below 180 degrees: exported as "
                       "diffuse emitters ({items})",
        "world-nodes": "{n} world(s) use nodes other than Background with a colour or an "
                       "Environment Texture: exported as the world's viewport colour ({items})",
        "env-projection": "{n} environment texture(s) are not equirectangular: exported as "
                          "the world's viewport colour ({items})",
        "env-mapping": "{n} environment texture(s) have a linked Vector input (rotation): "
                       "exported unrotated ({items})",
        "render-border": "{n} scene(s) render a border region: the exporter writes the whole "
                         "frame ({items})",
    }

    def __init__(self):
        self._items = {}

    def add(self, kind, item):
        """Record that ``item`` (a name) has the problem ``kind`` (a key of KINDS)."""
        items = self._items.setdefault(kind, [])
        if item not in items:
            items.append(item)

    def kinds(self):
        """The kinds reported so far, in order of first report."""
        return list(self._items)

    def items(self, kind):
        """The names reported for ``kind`` (empty if none)."""
        return list(self._items.get(kind, []))

    def messages(self):
        """One message per kind, e.g. '2 material(s) use nodes other than ... (A, B)'."""
        out = []
        for kind, items in self._items.items():
            shown = ", ".join(items[:5]) + (", ..." if len(items) > 5 else "")
            out.append(self.KINDS[kind].format(n=len(items), items=shown))
        return out
