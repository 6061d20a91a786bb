# Sourced by the studies that measure the assimp spider mesh: sets `mesh` to its path, installing
# the Debian package assimp-testmodels when it is missing.
mesh=/usr/share/assimp/models/OBJ/spider.obj
if [[ ! -f $mesh ]]; then
  echo "installing assimp-testmodels for the spider mesh"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq assimp-testmodels >/dev/null
fi
